#include "solvers/matrix_market.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

namespace ryushi::solvers {

namespace {
[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  throw std::invalid_argument(path + ":" + std::to_string(line) + ": " + what);
}
}  // namespace

CsrMatrix<double> read_matrix_market(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read the matrix file");
  std::string line;
  std::size_t no = 1;
  if (!std::getline(in, line) || line.rfind("%%MatrixMarket", 0) != 0)
    fail(path, no, "not a Matrix Market file (first line must start with %%MatrixMarket)");
  std::string banner, object, format, field, symmetry;
  std::istringstream(line) >> banner >> object >> format >> field >> symmetry;
  if (object != "matrix" || format != "coordinate" || (field != "real" && field != "integer"))
    fail(path, no, "only 'matrix coordinate real' is supported");
  bool symmetric = symmetry == "symmetric";
  if (!symmetric && symmetry != "general") fail(path, no, "symmetry must be general or symmetric");
  std::size_t rows = 0, cols = 0, entries = 0;
  while (std::getline(in, line)) {
    ++no;
    if (line.empty() || line[0] == '%') continue;
    std::istringstream s(line);
    if (!(s >> rows >> cols >> entries)) fail(path, no, "expected 'rows cols entries'");
    break;
  }
  std::vector<std::tuple<std::uint32_t, std::uint32_t, double>> t;
  t.reserve(symmetric ? 2 * entries : entries);
  std::size_t read = 0;
  while (read < entries && std::getline(in, line)) {
    ++no;
    if (line.empty() || line[0] == '%') continue;
    std::istringstream s(line);
    std::size_t r, c;
    double v;
    if (!(s >> r >> c >> v)) fail(path, no, "expected 'row column value'");
    if (r < 1 || r > rows || c < 1 || c > cols) fail(path, no, "index outside the " + std::to_string(rows) + " x " + std::to_string(cols) + " matrix");
    if (!std::isfinite(v)) fail(path, no, "non-finite value");
    t.emplace_back(r - 1, c - 1, v);
    if (symmetric && r != c) t.emplace_back(c - 1, r - 1, v);
    ++read;
  }
  if (read != entries) fail(path, no, "file ends after " + std::to_string(read) + " of " + std::to_string(entries) + " entries");
  return csr_from_triplets<double>(rows, cols, std::move(t));
}

void write_matrix_market(const std::string& path, const CsrMatrix<double>& A) {
  std::ofstream out(path);
  if (!out) throw std::invalid_argument(path + ": cannot write");
  out.precision(17);
  out << "%%MatrixMarket matrix coordinate real general\n" << A.rows << " " << A.cols << " " << A.nonzeros() << "\n";
  for (std::size_t r = 0; r < A.rows; ++r)
    for (auto k = A.row_ptr[r]; k < A.row_ptr[r + 1]; ++k) out << r + 1 << " " << A.col[k] + 1 << " " << A.val[k] << "\n";
}

std::vector<double> read_values(const std::string& path, std::size_t columns) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read");
  std::vector<double> v;
  std::string line;
  std::size_t no = 0;
  while (std::getline(in, line)) {
    ++no;
    if (line.empty() || line[0] == '%' || line[0] == '#') continue;
    std::istringstream s(line);
    if (columns == 0) {  // every number on the line
      for (double x; s >> x;) v.push_back(x);
      continue;
    }
    for (std::size_t c = 0; c < columns; ++c) {
      double x;
      if (!(s >> x)) fail(path, no, "expected " + std::to_string(columns) + " number(s)");
      v.push_back(x);
    }
  }
  return v;
}

void write_values(const std::string& path, const std::vector<double>& v, std::size_t columns) {
  std::ofstream out(path);
  if (!out) throw std::invalid_argument(path + ": cannot write");
  out.precision(17);
  for (std::size_t i = 0; i < v.size(); ++i) out << v[i] << ((i + 1) % columns ? " " : "\n");
}

}  // namespace ryushi::solvers
