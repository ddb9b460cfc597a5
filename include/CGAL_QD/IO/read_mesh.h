// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_READ_MESH_H
#define CGAL_QD_IO_READ_MESH_H

/// \file read_mesh.h
/// Reading a mesh file that a user brings: `read_polygon_soup()` checks the
/// file's structure before anything is allocated (so a truncated file, wrong
/// counts or garbage numbers give an error instead of a crash or a huge
/// allocation), and `read_and_repair_mesh()` then repairs the soup into a
/// triangle mesh with `repair_polygon_soup_to_mesh()`.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/repair_mesh.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace IO {

/// The outcome of `read_polygon_soup()`: `OK`, `CANNOT_OPEN_FILE` or
/// `INVALID_FILE`, with a sentence in `message`.
struct Read_status
{
  Error_code status = Error_code::OK;
  std::string message;
  explicit operator bool() const { return status == Error_code::OK; }
};

} // namespace IO

namespace internal {

// the words of `line` (separated by the blanks of the "C" locale, up to a
// word that starts a comment with '#') into `words`, whose strings are reused
inline void split_words(const std::string& line, std::vector<std::string>& words)
{
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; };
  std::size_t n = 0;
  const char *s = line.data(), *end = s + line.size();
  for(;;) {
    while(s != end && blank(*s)) ++s;
    if(s == end || *s == '#') break;
    const char* b = s;
    while(s != end && !blank(*s)) ++s;
    if(n < words.size())
      words[n].assign(b, s);
    else
      words.emplace_back(b, s);
    ++n;
  }
  words.resize(n);
}

inline std::vector<std::string> split_words(const std::string& line)
{
  std::vector<std::string> words;
  split_words(line, words);
  return words;
}

inline bool parse_count(const std::string& word, std::size_t& value)
{
  if(word.empty() || !std::isdigit(static_cast<unsigned char>(word[0]))) return false;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(word.c_str(), &end, 10);
  if(errno != 0 || *end != '\0') return false;
  value = static_cast<std::size_t>(v);
  return true;
}

// a number; NaN and infinite values are returned as such (the repair names them)
inline bool parse_real(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

// ASCII OFF, one vertex or face per line, as every common writer does: a
// header [ST][C][N][4]OFF (counts on the same line or the next), vertices whose
// first three numbers are the position (normals, colours, texture coordinates
// after them are skipped; 4OFF divides by w), faces "k i_1 ... i_k [colour]".
template <class Point, class Polygon>
IO::Read_status read_ascii_OFF(std::istream& in, std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  auto invalid = [](const std::string& why) { return IO::Read_status{Error_code::INVALID_FILE, why}; };
  std::string line;
  std::size_t line_number = 0;
  auto next_words = [&](std::vector<std::string>& words) {
    while(std::getline(in, line)) {
      ++line_number;
      split_words(line, words);
      if(!words.empty()) return true;
    }
    return false;
  };
  std::vector<std::string> words;
  if(!next_words(words)) return invalid("the file is empty");
  const std::string& header = words[0];
  if(header.size() < 3 || header.compare(header.size() - 3, 3, "OFF") != 0)
    return invalid("the first word is '" + header.substr(0, 20) + "', not an OFF header");
  const std::string prefix = header.substr(0, header.size() - 3);
  bool homogeneous = false;
  for(std::size_t i = 0; i < prefix.size(); ++i) {
    if(prefix.compare(i, 2, "ST") == 0) { ++i; continue; }
    if(prefix[i] == 'C' || prefix[i] == 'N') continue;
    if(prefix[i] == '4') { homogeneous = true; continue; }
    return invalid("the OFF variant '" + header + "' is not supported");
  }
  words.erase(words.begin());
  if(words.empty() && !next_words(words)) return invalid("the file ends before the vertex and face counts");
  std::size_t nv = 0, nf = 0;
  if(words.size() < 2 || !parse_count(words[0], nv) || !parse_count(words[1], nf))
    return invalid("line " + std::to_string(line_number) + ": the vertex and face counts are not two non-negative integers");
  points.clear();
  polygons.clear();
  // a vertex or a face takes at least a line of 2 bytes: never reserve more than the file can hold
  const std::size_t cap = 1 << 20;
  points.reserve((std::min)(nv, cap));
  polygons.reserve((std::min)(nf, cap));
  for(std::size_t i = 0; i < nv; ++i) {
    if(!next_words(words))
      return invalid("the file is truncated: it announces " + std::to_string(nv) + " vertices and has " +
                     std::to_string(i));
    double c[4] = {0, 0, 0, 1};
    const std::size_t n = homogeneous ? 4 : 3;
    if(words.size() < n) return invalid("line " + std::to_string(line_number) + ": a vertex needs " + std::to_string(n) + " numbers");
    for(std::size_t k = 0; k < n; ++k)
      if(!parse_real(words[k], c[k]))
        return invalid("line " + std::to_string(line_number) + ": '" + words[k].substr(0, 20) + "' is not a number");
    if(homogeneous) {
      for(int k = 0; k < 3; ++k) c[k] /= c[3];
    }
    points.emplace_back(c[0], c[1], c[2]);
  }
  for(std::size_t i = 0; i < nf; ++i) {
    if(!next_words(words))
      return invalid("the file is truncated: it announces " + std::to_string(nf) + " faces and has " +
                     std::to_string(i));
    std::size_t k = 0;
    if(!parse_count(words[0], k) || k == 0 || k + 1 > words.size())
      return invalid("line " + std::to_string(line_number) + ": a face must start with its number of corners, followed by as many indices");
    Polygon polygon(k);
    for(std::size_t j = 0; j < k; ++j) {
      std::size_t id = 0;
      if(!parse_count(words[j + 1], id))
        return invalid("line " + std::to_string(line_number) + ": '" + words[j + 1].substr(0, 20) + "' is not a vertex index");
      if(id >= nv)
        return invalid("line " + std::to_string(line_number) + ": vertex index " + std::to_string(id) +
                       " is out of range (" + std::to_string(nv) + " vertices)");
      polygon[j] = id;
    }
    polygons.push_back(std::move(polygon));
  }
  return IO::Read_status{};
}

// Walks a binary OFF file as CGAL's reader will read it (big-endian 32-bit
// counts, then per vertex its floats, per face "k i_1 ... i_k m c_1 ... c_m"
// with at most 4 colour floats), checking that the counts are not negative and
// that every vertex and face fits in the file, so that CGAL's reader never
// sizes anything from a number the file cannot hold. `size` is the file's size.
inline IO::Read_status check_binary_OFF_structure(std::istream& in, std::uintmax_t size)
{
  auto invalid = [](const std::string& why) { return IO::Read_status{Error_code::INVALID_FILE, why}; };
  std::string line;
  std::vector<std::string> words;
  while(std::getline(in, line)) {
    words = split_words(line);
    if(!words.empty() && words[0][0] != '#') break;
  }
  if(words.size() < 2 || words[0].size() < 3 || words[0].compare(words[0].size() - 3, 3, "OFF") != 0 ||
     words[1] != "BINARY")
    return invalid("the binary OFF header is not '[prefix]OFF BINARY' on a line of its own");
  const std::string prefix = words[0].substr(0, words[0].size() - 3);
  bool homogeneous = false, normals = false, colours = false, textures = false;
  for(std::size_t i = 0; i < prefix.size(); ++i) {
    if(prefix.compare(i, 2, "ST") == 0) { textures = true; ++i; continue; }
    if(prefix[i] == 'C') { colours = true; continue; }
    if(prefix[i] == 'N') { normals = true; continue; }
    if(prefix[i] == '4') { homogeneous = true; continue; }
    return invalid("the binary OFF variant '" + words[0] + "' is not supported");
  }
  const std::uintmax_t h = homogeneous ? 1 : 0;
  const std::uintmax_t vertex_bytes =
      4 * ((3 + h) + (normals ? 3 + h : 0) + (colours ? 3 : 0) + (textures ? 2 + h : 0));
  auto read_int = [&](std::int32_t& value) {
    unsigned char b[4];
    if(!in.read(reinterpret_cast<char*>(b), 4)) return false;
    value = static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                      (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
    return true;
  };
  std::int32_t nv = 0, nf = 0, ne = 0;
  if(!read_int(nv) || !read_int(nf) || !read_int(ne))
    return invalid("the binary OFF file ends before its vertex, face and edge counts");
  // CGAL's reader doubles the edge count in an int: keep it a plausible count
  if(nv < 0 || nf < 0 || ne < 0 || ne > (1 << 29))
    return invalid("the binary OFF file announces a negative number of vertices, faces or edges, or too many edges");
  const std::streamoff at = in.tellg();
  if(at < 0) return invalid("the binary OFF file cannot be read");
  std::uintmax_t position = static_cast<std::uintmax_t>(at);
  if((size - position) / vertex_bytes < std::uintmax_t(nv))
    return invalid("the binary OFF file is truncated: it announces " + std::to_string(nv) +
                   " vertices and holds fewer");
  position += std::uintmax_t(nv) * vertex_bytes;
  for(std::int32_t i = 0; i < nf; ++i) {
    std::int32_t k = 0, m = 0;
    in.seekg(static_cast<std::streamoff>(position));
    if(size - position < 4 || !read_int(k))
      return invalid("the binary OFF file is truncated: it announces " + std::to_string(nf) + " faces and holds " +
                     std::to_string(i));
    if(k < 1 || k > nv || (size - position - 4) / 4 < std::uintmax_t(k) + 1)
      return invalid("face " + std::to_string(i) + " of the binary OFF file has " + std::to_string(k) +
                     " corners, which the file cannot hold");
    position += 4 + 4 * std::uintmax_t(k);
    in.seekg(static_cast<std::streamoff>(position));
    if(!read_int(m) || m < 0 || m > 4 || (size - position - 4) / 4 < std::uintmax_t(m))
      return invalid("face " + std::to_string(i) + " of the binary OFF file has a malformed colour");
    position += 4 + 4 * std::uintmax_t(m);
  }
  return IO::Read_status{};
}

// Walks the elements of a PLY file (ASCII or binary) as its header declares
// them, checking that every element, scalar and list fits in the file, so that
// CGAL's reader never allocates what the file does not hold.
inline IO::Read_status check_PLY_structure(std::istream& in)
{
  auto invalid = [](const std::string& why) { return IO::Read_status{Error_code::INVALID_FILE, why}; };
  struct Property { bool list = false; int count_size = 0, value_size = 0; };
  struct Element { std::string name; std::size_t count = 0; std::vector<Property> properties; };
  auto type_size = [](const std::string& t) -> int {
    if(t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if(t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if(t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if(t == "double" || t == "float64") return 8;
    return 0;
  };
  std::string line;
  if(!std::getline(in, line) || line.compare(0, 3, "ply") != 0) return invalid("the file does not start with 'ply'");
  std::vector<Element> elements;
  int format = -1; // 0 ascii, 1 little endian, 2 big endian
  bool ended = false;
  for(std::size_t number = 2; std::getline(in, line); ++number) {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string key;
    words >> key;
    if(key == "end_header") { ended = true; break; }
    // CGAL's reader takes the format from the second line and from no other
    if((key == "format") != (number == 2)) return invalid("the PLY format must be given on the second line, once");
    if(key == "format") {
      std::string f;
      words >> f;
      format = f == "ascii" ? 0 : f == "binary_little_endian" ? 1 : f == "binary_big_endian" ? 2 : -1;
      if(format < 0) return invalid("unknown PLY format '" + f.substr(0, 30) + "'");
    }
    else if(key == "element") {
      Element e;
      std::string count;
      words >> e.name >> count;
      if(!parse_count(count, e.count)) return invalid("the count of PLY element '" + e.name.substr(0, 30) + "' is not a non-negative integer");
      elements.push_back(e);
    }
    else if(key == "property") {
      if(elements.empty()) return invalid("a PLY property comes before any element");
      std::string type;
      words >> type;
      Property p;
      if(type == "list") {
        std::string count_type, value_type;
        words >> count_type >> value_type;
        p.list = true;
        p.count_size = type_size(count_type);
        p.value_size = type_size(value_type);
        if(p.count_size == 0 || p.value_size == 0) return invalid("unknown PLY list type '" + count_type + " " + value_type + "'");
      }
      else {
        p.value_size = type_size(type);
        if(p.value_size == 0) return invalid("unknown PLY property type '" + type.substr(0, 30) + "'");
      }
      elements.back().properties.push_back(p);
    }
    else if(key != "comment" && key != "obj_info" && !key.empty())
      return invalid("unknown PLY header line '" + line.substr(0, 40) + "'");
  }
  if(!ended) return invalid("the PLY header has no 'end_header'");
  if(format < 0) return invalid("the PLY header has no format line");
  // an element without properties takes no room: its count could never be checked against the file
  for(const Element& e : elements)
    if(e.count > 0 && e.properties.empty())
      return invalid("PLY element '" + e.name.substr(0, 30) + "' announces " + std::to_string(e.count) +
                     " entries without any property");
  for(const Element& e : elements) {
    for(std::size_t i = 0; i < e.count; ++i) {
      if(format == 0) {
        if(!std::getline(in, line))
          return invalid("the file is truncated: PLY element '" + e.name.substr(0, 30) + "' announces " +
                         std::to_string(e.count) + " lines and has " + std::to_string(i));
        const std::vector<std::string> words = split_words(line);
        std::size_t w = 0;
        for(const Property& p : e.properties) {
          std::size_t n = 1;
          if(p.list) {
            if(w >= words.size() || !parse_count(words[w], n))
              return invalid("a list of PLY element '" + e.name.substr(0, 30) + "' does not start with its length");
            ++w;
          }
          for(std::size_t k = 0; k < n; ++k, ++w) {
            double value;
            if(w >= words.size() || !parse_real(words[w], value))
              return invalid("a line of PLY element '" + e.name.substr(0, 30) + "' has too few or bad numbers");
          }
        }
        // CGAL's reader reads numbers, not lines: an extra number would shift it
        if(w != words.size())
          return invalid("a line of PLY element '" + e.name.substr(0, 30) + "' has more numbers than its properties");
      }
      else {
        for(const Property& p : e.properties) {
          std::uint64_t n = 1;
          if(p.list) {
            unsigned char bytes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
            if(!in.read(reinterpret_cast<char*>(bytes), p.count_size))
              return invalid("the file is truncated inside PLY element '" + e.name.substr(0, 30) + "'");
            n = 0;
            for(int b = 0; b < p.count_size; ++b)
              n |= std::uint64_t(bytes[format == 1 ? b : p.count_size - 1 - b]) << (8 * b);
          }
          const std::uint64_t bytes = n * std::uint64_t(p.value_size);
          if(n > (std::uint64_t(1) << 32) || !in.ignore(static_cast<std::streamsize>(bytes)) ||
             in.gcount() != static_cast<std::streamsize>(bytes))
            return invalid("the file is truncated inside PLY element '" + e.name.substr(0, 30) + "'");
        }
      }
    }
  }
  return IO::Read_status{};
}

inline std::string lowercase_extension(const std::string& filename)
{
  std::string ext = std::filesystem::path(filename).extension().string();
  if(!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

} // namespace internal

namespace IO {

/// reads the points and polygons of a mesh file (OFF, OBJ, PLY or STL, by its
/// extension in any letter case), checking the file's structure first.
///
/// ASCII OFF is read here, one vertex or face per line; binary OFF, OBJ, PLY
/// and STL by CGAL's readers, binary OFF and PLY after a walk over their
/// declared vertices and faces that checks that the file holds them.
/// NaN and infinite coordinates are read as such; indices are not checked
/// against the number of points (`repair_polygon_soup_to_mesh()` does).
///
/// \returns `OK`, `CANNOT_OPEN_FILE` (missing, a directory, unreadable) or
///   `INVALID_FILE` (empty, unknown extension, truncated, wrong counts,
///   unreadable numbers), with a sentence in `message`; on failure `points`
///   and `polygons` are empty.
template <class Point, class Polygon>
Read_status read_polygon_soup(const std::string& filename, std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  points.clear();
  polygons.clear();
  auto fail = [&](Error_code code, const std::string& why) {
    points.clear();
    polygons.clear();
    return Read_status{code, why};
  };
  std::error_code ec;
  if(!std::filesystem::exists(filename, ec)) return fail(Error_code::CANNOT_OPEN_FILE, "'" + filename + "' does not exist");
  if(std::filesystem::is_directory(filename, ec))
    return fail(Error_code::CANNOT_OPEN_FILE, "'" + filename + "' is a directory");
  std::ifstream in(filename, std::ios::binary);
  if(!in) return fail(Error_code::CANNOT_OPEN_FILE, "'" + filename + "' cannot be opened");
  const auto size = std::filesystem::file_size(filename, ec);
  if(ec || size == 0) return fail(Error_code::INVALID_FILE, "'" + filename + "' is empty");
  const std::string ext = internal::lowercase_extension(filename);
  Read_status s;
  try {
    if(ext == "off") {
      std::string first;
      {
        std::string line;
        while(std::getline(in, line) && internal::split_words(line).empty()) {}
        first = line;
      }
      const std::vector<std::string> words = internal::split_words(first);
      in.clear();
      in.seekg(0);
      if(std::find(words.begin(), words.end(), "BINARY") != words.end()) {
        s = internal::check_binary_OFF_structure(in, size);
        in.clear();
        in.seekg(0);
        if(s && !CGAL::IO::read_OFF(in, points, polygons))
          s = Read_status{Error_code::INVALID_FILE, "the binary OFF file is truncated or malformed"};
      }
      else
        s = internal::read_ascii_OFF(in, points, polygons);
    }
    else if(ext == "ply") {
      s = internal::check_PLY_structure(in);
      if(s) {
        in.clear();
        in.seekg(0);
        if(!CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false)))
          s = Read_status{Error_code::INVALID_FILE, "the PLY file is malformed"};
      }
    }
    else if(ext == "obj") {
      std::ifstream text(filename);
      if(!CGAL::IO::read_OBJ(text, points, polygons))
        s = Read_status{Error_code::INVALID_FILE, "the OBJ file is malformed"};
    }
    else if(ext == "stl") {
      if(!CGAL::IO::read_STL(in, points, polygons))
        s = Read_status{Error_code::INVALID_FILE, "the STL file is truncated or malformed"};
    }
    else
      s = Read_status{Error_code::INVALID_FILE,
                      "the extension '" + ext + "' is not one of the formats read (off, obj, ply, stl)"};
  }
  catch(const std::exception& e) {
    s = Read_status{Error_code::INVALID_FILE, std::string("the file could not be read (") + e.what() + ")"};
  }
  if(!s) return fail(s.status, s.message);
  if(polygons.empty()) return fail(Error_code::INVALID_FILE, "the file has no face");
  return s;
}

/// reads a mesh file with `read_polygon_soup()` and repairs it into a
/// triangle mesh with `repair_polygon_soup_to_mesh()`.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` whose point type is a
///   CGAL point (the points are read as that type)
/// \param filename an OFF, OBJ, PLY or STL file
/// \param pm the output mesh (cleared first; empty on failure)
/// \param np optional named parameters, passed to `repair_polygon_soup_to_mesh()`
/// \returns the repair report; on failure `status` is one of
///   `read_polygon_soup()`'s or `repair_polygon_soup_to_mesh()`'s, and `message`
///   says what is wrong
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Repair_report read_and_repair_mesh(const std::string& filename, PolygonMesh& pm,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  const Read_status s = read_polygon_soup(filename, points, polygons);
  if(!s) {
    CGAL::clear(pm);
    Repair_report r;
    r.status = s.status;
    r.message = s.message;
    return r;
  }
  return repair_polygon_soup_to_mesh(std::move(points), std::move(polygons), pm, np);
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_READ_MESH_H
