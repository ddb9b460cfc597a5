// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LOWER_TRIANGLE_H
#define CGAL_QD_INTERNAL_LOWER_TRIANGLE_H

// The lower triangle of a symmetric sparse matrix assembled from its entries
// straight into compressed column storage.

#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The entries (i, j, v), i >= j, of an n x n matrix, added in any order; an
// entry given more than once takes the sum of its values in the order given.
// `assemble()` writes the matrix in compressed column storage, the rows of
// every column sorted: the matrix, to the last bit, that
// `Eigen::SparseMatrix::setFromTriplets()` makes of the same triplets (it too
// sums in the order given), without the row-major copy it makes first and
// transposes. The diagonal, which a Laplacian adds to at every edge, is summed
// in place as the entries come.
class Lower_triangle_assembly
{
public:
  Lower_triangle_assembly(long n, std::size_t expected_entries)
      : m_n(n), m_diagonal(static_cast<std::size_t>(n), 0.), m_has_diagonal(static_cast<std::size_t>(n), 0)
  {
    m_entries.reserve(expected_entries);
  }

  void add(long i, long j, double v)
  {
    if(i != j) {
      m_entries.push_back(Entry{static_cast<int>(i), static_cast<int>(j), v});
      return;
    }
    const std::size_t d = static_cast<std::size_t>(i);
    if(m_has_diagonal[d]) {
      m_diagonal[d] += v;
    } else {
      m_diagonal[d] = v;
      m_has_diagonal[d] = 1;
    }
  }

  // the matrix of the entries added, which are consumed
  void assemble(Eigen::SparseMatrix<double>& A)
  {
    const std::size_t columns = static_cast<std::size_t>(m_n);
    // the entries below the diagonal by column, each column in the order given
    std::vector<int> start(columns + 1, 0);
    for(const Entry& e : m_entries) ++start[static_cast<std::size_t>(e.col) + 1];
    for(std::size_t j = 0; j < columns; ++j) start[j + 1] += start[j];
    std::vector<int> next(start.begin(), start.end() - 1);
    std::vector<std::pair<int, double>> by_column(m_entries.size());
    for(const Entry& e : m_entries)
      by_column[static_cast<std::size_t>(next[static_cast<std::size_t>(e.col)]++)] = {e.row, e.val};
    std::vector<Entry>().swap(m_entries);

    A.resize(m_n, m_n);
    A.resizeNonZeros(static_cast<Eigen::Index>(by_column.size() + columns));
    int* outer = A.outerIndexPtr();
    int* inner = A.innerIndexPtr();
    double* value = A.valuePtr();
    std::vector<int> slot(columns, -1);  // where the column being written holds a row
    int nnz = 0;
    outer[0] = 0;
    for(std::size_t j = 0; j < columns; ++j) {
      if(m_has_diagonal[j]) {  // the smallest row of the column
        inner[nnz] = static_cast<int>(j);
        value[nnz++] = m_diagonal[j];
      }
      const int first = nnz;
      for(int k = start[j]; k < start[j + 1]; ++k) {
        const auto& [i, v] = by_column[static_cast<std::size_t>(k)];
        int& s = slot[static_cast<std::size_t>(i)];
        if(s >= first) {
          value[s] += v;
        } else {
          s = nnz;
          inner[nnz] = i;
          value[nnz++] = v;
        }
      }
      // the rows below the diagonal sorted (a few, so by insertion), each value with its row
      for(int k = first + 1; k < nnz; ++k) {
        const int i = inner[k];
        const double v = value[k];
        int p = k;
        for(; p > first && inner[p - 1] > i; --p) {
          inner[p] = inner[p - 1];
          value[p] = value[p - 1];
        }
        inner[p] = i;
        value[p] = v;
      }
      outer[j + 1] = nnz;
    }
    A.data().resize(static_cast<Eigen::Index>(nnz));
  }

private:
  struct Entry
  {
    int row, col;
    double val;
  };
  long m_n;
  std::vector<Entry> m_entries;
  std::vector<double> m_diagonal;
  std::vector<char> m_has_diagonal;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LOWER_TRIANGLE_H
