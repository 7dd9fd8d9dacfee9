#pragma once
// Compressed sparse row matrix in double or float. The solver library depends on nothing in
// ecs/ or systems/: it takes CSR matrices (and, for multigrid, coordinates) so it can be tested
// and benchmarked alone.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace ryushi::solvers {

// A CSR matrix's arrays without ownership: the multigrid's finest level reads the pressure
// matrix's row pointers and columns through it instead of copying them (a third of the matrix's
// bytes; at 1.28M unknowns a 160 MB copy per step), with values of its own precision.
template <class T>
struct CsrView {
  std::size_t rows = 0;
  const std::uint64_t* row_ptr = nullptr;
  const std::uint32_t* col = nullptr;
  const T* val = nullptr;
  std::size_t nonzeros() const { return rows ? row_ptr[rows] : 0; }
};

template <class T>
struct CsrMatrix {
  std::size_t rows = 0, cols = 0;
  std::vector<std::uint64_t> row_ptr{0};
  std::vector<std::uint32_t> col;
  std::vector<T> val;

  std::size_t nonzeros() const { return val.size(); }
  CsrView<T> view() const { return {rows, row_ptr.data(), col.data(), val.data()}; }
  std::size_t bytes() const {
    return row_ptr.size() * sizeof(std::uint64_t) + col.size() * sizeof(std::uint32_t) + val.size() * sizeof(T);
  }

  // Throws std::invalid_argument naming the first inconsistency (row pointers, column range,
  // non-finite value).
  void validate() const {
    if (row_ptr.size() != rows + 1) throw std::invalid_argument("CSR: row_ptr has the wrong length");
    if (row_ptr.front() != 0 || row_ptr.back() != val.size() || col.size() != val.size())
      throw std::invalid_argument("CSR: row_ptr does not match the number of entries");
    for (std::size_t r = 0; r < rows; ++r) {
      if (row_ptr[r + 1] < row_ptr[r]) throw std::invalid_argument("CSR: row_ptr decreases at row " + std::to_string(r));
      for (auto k = row_ptr[r]; k < row_ptr[r + 1]; ++k) {
        if (col[k] >= cols)
          throw std::invalid_argument("CSR: column " + std::to_string(col[k]) + " out of range in row " + std::to_string(r));
        if (!std::isfinite(static_cast<double>(val[k])))
          throw std::invalid_argument("CSR: non-finite entry in row " + std::to_string(r) + ", column " + std::to_string(col[k]));
      }
    }
  }

  std::vector<T> diagonal() const {
    std::vector<T> d(rows, T(0));
    for (std::size_t r = 0; r < rows; ++r)
      for (auto k = row_ptr[r]; k < row_ptr[r + 1]; ++k)
        if (col[k] == r) d[r] += val[k];
    return d;
  }
};

// Builds a CSR matrix from (row, column, value) triplets; duplicates are summed and columns
// sorted within each row.
template <class T>
CsrMatrix<T> csr_from_triplets(std::size_t rows, std::size_t cols,
                               std::vector<std::tuple<std::uint32_t, std::uint32_t, T>> triplets);

}  // namespace ryushi::solvers
