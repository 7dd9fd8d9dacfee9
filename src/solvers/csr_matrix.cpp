#include "solvers/csr_matrix.hpp"

#include <algorithm>
#include <tuple>

namespace ryushi::solvers {

template <class T>
CsrMatrix<T> csr_from_triplets(std::size_t rows, std::size_t cols,
                               std::vector<std::tuple<std::uint32_t, std::uint32_t, T>> t) {
  std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) < std::get<0>(b) : std::get<1>(a) < std::get<1>(b);
  });
  CsrMatrix<T> A;
  A.rows = rows;
  A.cols = cols;
  A.row_ptr.assign(rows + 1, 0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    auto [r, c, v] = t[k];
    if (r >= rows || c >= cols) throw std::invalid_argument("triplet outside the matrix");
    if (!A.col.empty() && k > 0 && std::get<0>(t[k - 1]) == r && std::get<1>(t[k - 1]) == c) {
      A.val.back() += v;  // duplicate entry
      continue;
    }
    A.col.push_back(c);
    A.val.push_back(v);
    ++A.row_ptr[r + 1];
  }
  for (std::size_t r = 0; r < rows; ++r) A.row_ptr[r + 1] += A.row_ptr[r];
  return A;
}

template CsrMatrix<double> csr_from_triplets<double>(std::size_t, std::size_t,
                                                     std::vector<std::tuple<std::uint32_t, std::uint32_t, double>>);
template CsrMatrix<float> csr_from_triplets<float>(std::size_t, std::size_t,
                                                   std::vector<std::tuple<std::uint32_t, std::uint32_t, float>>);

}  // namespace ryushi::solvers
