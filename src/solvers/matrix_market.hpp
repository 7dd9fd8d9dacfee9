#pragma once
// Matrix Market (coordinate, real, general or symmetric) and plain vector files, so a system
// can be handed to external solvers (hypre, AMGCL) and back: `ryushi solve A.mtx --rhs b.txt
// --coords x.txt`. Errors throw std::invalid_argument("FILE:LINE: problem").
#include <string>
#include <vector>

#include "solvers/csr_matrix.hpp"

namespace ryushi::solvers {

CsrMatrix<double> read_matrix_market(const std::string& path);
void write_matrix_market(const std::string& path, const CsrMatrix<double>& A);
// `columns` values per line (1 for vectors; 0 takes every number on each line, for
// coordinates), flattened row-major.
std::vector<double> read_values(const std::string& path, std::size_t columns = 1);
void write_values(const std::string& path, const std::vector<double>& v, std::size_t columns = 1);

}  // namespace ryushi::solvers
