#pragma once
// `ryushi run --dump-matrix DIR [--dump-step N]` for MPH-I: at step N writes the velocity
// equation of that step (mph_velocity_system.hpp), so the solvers can be compared on the very
// same system (the MPH-I paper's Fig. 3):
//   A.mtx  the matrix (Matrix Market), D rows per fluid particle
//   b.txt  the right-hand side, one value per line
//   x.txt  the coordinates of each fluid particle, D values per line (one line per D rows)
//   u.txt  the solution ryushi's solve returned, one value per line
// `ryushi solve DIR/A.mtx --rhs DIR/b.txt --coords DIR/x.txt --block-size D` solves it again.
// Each file is written to NAME.tmp and renamed.
#include <filesystem>
#include <string>
#include <vector>

#include "ecs/io.hpp"
#include "solvers/matrix_market.hpp"
#include "systems/mph/mph_velocity_system.hpp"
#include "systems/pressure/pressure_system_dump.hpp"

namespace ryushi {

template <int D>
class MphSystemDump final : public System<D> {
 public:
  MphSystemDump(std::filesystem::path dir, long long step) : dir_(std::move(dir)), step_(step) {}
  std::string name() const override { return "mph_system_dump"; }
  static constexpr auto io = Io{reads(mph_system_resource, components::velocity, resources::step)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, v, step] = io.fetch(ctx);
    if (step != step_) return;
    std::vector<double> solution(sys.A.rows);
    for (std::size_t r = 0; r < sys.particle_of_block.size(); ++r)
      for (int a = 0; a < D; ++a) solution[r * D + a] = v[sys.particle_of_block[r]][a];
    std::filesystem::create_directories(dir_);
    auto publish = [&](const std::string& name, auto&& write) { publish_dump_file(dir_, name, write); };
    publish("A.mtx", [&](const std::string& f) { solvers::write_matrix_market(f, sys.A); });
    publish("b.txt", [&](const std::string& f) { solvers::write_values(f, sys.b); });
    publish("x.txt", [&](const std::string& f) { solvers::write_values(f, sys.coordinates, D); });
    publish("u.txt", [&](const std::string& f) { solvers::write_values(f, solution); });
  }

 private:
  std::filesystem::path dir_;
  long long step_;
};

}  // namespace ryushi
