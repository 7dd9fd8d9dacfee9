// Speed against accuracy of every operator: ns per particle at 1e6 particles (2D: 1000^2 at
// d = 1e-3; 3D: 100^3 at d = 1e-2), 2 threads by default, beside the interior RMSE of the patch
// test at d = 1/80 (2D) and 1/40 (3D), regular and 20% disordered.
// Usage: ryushi_bench_operators [CSV_OUT] [THREADS]. docs/operators.md holds the table.
#include <tbb/global_control.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "verification/patch_test.hpp"

using namespace ryushi;

int main(int argc, char** argv) {
  std::string csv_path = argc > 1 ? argv[1] : "";
  int threads = argc > 2 ? std::stoi(argv[2]) : 2;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "dim,operator,ns_per_particle,rmse_regular,rmse_disordered\n";
  }
  std::printf("| dim | operator | ns/particle (1e6, %d threads) | RMSE interior regular | RMSE interior 20%% disorder |\n", threads);
  std::printf("|---|---|---|---|---|\n");
  for (int dim : {2, 3}) {
    for (auto& op : patch_test_operators()) {
      PatchTestOptions o;
      o.dimension = dim;
      o.op = op;
      o.spacings = {dim == 2 ? 1e-3 : 1e-2};
      auto big = run_patch_test(o).rows[0];
      double ns = 1e9 * big.seconds / double(big.interior + big.boundary);
      o.spacings = {dim == 2 ? 1.0 / 80 : 1.0 / 40};
      double regular = run_patch_test(o).rows[0].rmse_interior;
      o.disorder = 0.2;
      double disordered = run_patch_test(o).rows[0].rmse_interior;
      std::printf("| %dD | %s | %.1f | %.3e | %.3e |\n", dim, op.c_str(), ns, regular, disordered);
      std::fflush(stdout);
      if (csv) csv << dim << "," << op << "," << ns << "," << regular << "," << disordered << "\n";
    }
  }
  return 0;
}
