#pragma once
// `ryushi run --dump-matrix DIR [--dump-step N]`: at step N (counted from 0) writes the pressure
// equation of that step so external solvers can be compared on the very same system:
//   A.mtx  the matrix (Matrix Market, coordinate real general)
//   b.txt  the right-hand side, one value per line
//   x.txt  the coordinates of the particle of each row, D values per line
//   p.txt  the solution ryushi's linear solve returned, one value per line
// `ryushi solve DIR/A.mtx --rhs DIR/b.txt --coords DIR/x.txt` solves it again. It reads the
// pressure column, so it runs after the linear solve; each file is written to NAME.tmp and
// renamed.
#include <filesystem>

#include "ecs/io.hpp"
#include "solvers/matrix_market.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

// Writes DIR/NAME through write(DIR/NAME.tmp) and a rename, so a reader never sees half a file.
template <class Write>
void publish_dump_file(const std::filesystem::path& dir, const std::string& name, Write&& write) {
  auto target = dir / name, tmp = dir / (name + ".tmp");
  write(tmp.string());
  std::filesystem::rename(tmp, target);
}

template <int D>
class PressureSystemDump final : public System<D> {
 public:
  PressureSystemDump(std::filesystem::path dir, long long step) : dir_(std::move(dir)), step_(step) {}
  std::string name() const override { return "pressure_system_dump"; }
  static constexpr auto io = Io{reads(pressure_system_resource, components::pressure, resources::step)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, p, step] = io.fetch(ctx);
    if (step != step_) return;
    std::vector<double> solution(sys.A.rows);
    for (std::size_t r = 0; r < sys.A.rows; ++r) solution[r] = p[sys.particle_of_row[r]];
    std::filesystem::create_directories(dir_);
    auto publish = [&](const std::string& name, auto&& write) { publish_dump_file(dir_, name, write); };
    publish("A.mtx", [&](const std::string& f) { solvers::write_matrix_market(f, sys.A); });
    publish("b.txt", [&](const std::string& f) { solvers::write_values(f, sys.b); });
    publish("x.txt", [&](const std::string& f) { solvers::write_values(f, sys.coordinates, D); });
    publish("p.txt", [&](const std::string& f) { solvers::write_values(f, solution); });
  }

 private:
  std::filesystem::path dir_;
  long long step_;
};

}  // namespace ryushi
