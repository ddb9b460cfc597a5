// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The output files of segment_mesh, all of them or none.

#ifndef CGAL_QD_PROGRAMS_OUTPUT_FILES_H
#define CGAL_QD_PROGRAMS_OUTPUT_FILES_H

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace segment_mesh {

// Files written next to their final names and renamed into place together
// once every one is complete: a failed run leaves none of its files behind
// (those of an earlier run into the same directory stay as they were).
class Output_files
{
public:
  explicit Output_files(const std::filesystem::path& dir) : m_dir(dir) {}
  ~Output_files() { discard(); }

  // the directory, created if needed; otherwise why not
  std::string open()
  {
    std::error_code ec;
    m_created = !std::filesystem::exists(m_dir, ec) && std::filesystem::create_directories(m_dir, ec);
    if(ec) return ec.message();
    if(!std::filesystem::is_directory(m_dir, ec)) return "it is not a directory";
    return std::string();
  }
  std::ofstream& file(const std::string& name)
  {
    m_names.push_back(name);
    m_streams.emplace_back(new std::ofstream(part(name), std::ios::binary));
    return *m_streams.back();
  }
  // true if every file was written and moved into place
  bool commit()
  {
    for(auto& s : m_streams) {
      s->close();
      if(!*s) return false;
    }
    std::error_code ec;
    for(const std::string& name : m_names) {
      std::filesystem::rename(part(name), m_dir / name, ec);
      if(ec) return false;
      m_moved.push_back(name);
    }
    m_names.clear();
    m_moved.clear();
    m_created = false;
    return true;
  }

private:
  std::filesystem::path part(const std::string& name) const { return m_dir / ("." + name + ".part"); }
  void discard()
  {
    std::error_code ec;
    m_streams.clear();
    for(const std::string& name : m_names) std::filesystem::remove(part(name), ec);
    for(const std::string& name : m_moved) std::filesystem::remove(m_dir / name, ec);  // a half-done commit
    if(m_created) std::filesystem::remove(m_dir, ec);  // only if it is empty again
  }

  std::filesystem::path m_dir;
  bool m_created = false;
  std::vector<std::string> m_names, m_moved;
  std::vector<std::unique_ptr<std::ofstream>> m_streams;
};

} // namespace segment_mesh

#endif // CGAL_QD_PROGRAMS_OUTPUT_FILES_H
