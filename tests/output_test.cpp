#include <doctest/doctest.h>
#include <hdf5.h>

#include "app/exit_codes.hpp"
#include "app/run.hpp"
#include "h5_read.hpp"
#include "test_util.hpp"

using namespace ryushi;
namespace fs = std::filesystem;

namespace {

// Dimensions of a dataset in an HDF5 file, empty if the file or dataset cannot be opened.
std::vector<hsize_t> dataset_dims(const fs::path& file, const std::string& name) {
  H5E_BEGIN_TRY {
    hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return {};
    hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    std::vector<hsize_t> dims;
    if (d >= 0) {
      hid_t s = H5Dget_space(d);
      dims.resize(H5Sget_simple_extent_ndims(s));
      H5Sget_simple_extent_dims(s, dims.data(), nullptr);
      H5Sclose(s);
      H5Dclose(d);
    }
    H5Fclose(f);
    return dims;
  }
  H5E_END_TRY;
}

double time_attribute(const fs::path& file) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t a = H5Aopen(f, "time", H5P_DEFAULT);
  double t = -1;
  H5Aread(a, H5T_NATIVE_DOUBLE, &t);
  H5Aclose(a);
  H5Fclose(f);
  return t;
}

std::size_t count_files(const fs::path& dir, const std::string& ext) {
  std::size_t n = 0;
  for (auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ext) ++n;
  return n;
}

}  // namespace

TEST_CASE("output: frames, xdmf, summary, profile, probes and trace are written whole") {
  auto out = test::scratch("output_run");
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  opt.trace = true;
  opt.end_time = 0.02;
  opt.sets = {"particles.spacing=0.025", "output.interval=0.01", "output.fields=[\"acceleration\", \"mass\"]"};
  REQUIRE(run_scene(opt) == kExitDone);

  auto f0 = out / "frames" / "frame_00000.h5", f2 = out / "frames" / "frame_00002.h5";
  REQUIRE(fs::exists(f2));
  auto n = dataset_dims(f2, "pressure");
  REQUIRE(n.size() == 1);
  // 2D vectors are stored with 3 components (z = 0), as ParaView's filters expect.
  CHECK(dataset_dims(f2, "position") == std::vector<hsize_t>{n[0], 3});
  CHECK(dataset_dims(f2, "velocity") == std::vector<hsize_t>{n[0], 3});
  CHECK(dataset_dims(f2, "acceleration") == std::vector<hsize_t>{n[0], 3});
  for (auto name : {"density", "kind", "id", "mass", "connectivity"}) CHECK(dataset_dims(f2, name) == n);
  auto z = test::read_dataset(f2, "position").values;
  double max_abs_z = 0;
  for (std::size_t i = 0; i < n[0]; ++i) max_abs_z = std::max(max_abs_z, std::abs(z[3 * i + 2]));
  CHECK(max_abs_z == 0.0);
  auto vertices = test::read_dataset(f2, "connectivity").values;
  CHECK(vertices.front() == 0);
  CHECK(vertices.back() == double(n[0] - 1));
  // Frames land on the output times: the step that crosses one is shortened.
  CHECK(time_attribute(f0) == 0.0);
  CHECK(time_attribute(out / "frames" / "frame_00001.h5") == 0.01);
  CHECK(time_attribute(f2) == 2 * 0.01);
  CHECK(count_files(out, ".tmp") == 0);

  auto xdmf = test::read_text(out / "particles.xdmf");
  CHECK(xdmf.find("frames/frame_00002.h5:/position") != std::string::npos);
  CHECK(xdmf.find("frames/frame_00002.h5:/connectivity") != std::string::npos);
  CHECK(xdmf.find("<Time Value=\"0.01\"/>") != std::string::npos);
  CHECK(xdmf.find("GeometryType=\"XYZ\"") != std::string::npos);
  CHECK(xdmf.find("CollectionType=\"Temporal\"") != std::string::npos);

  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "completed");
  CHECK(test::json_number(summary, "simulated_time") == doctest::Approx(0.02));
  CHECK(test::json_number(summary, "particles") == doctest::Approx(double(n[0])));
  CHECK(test::json_number(summary, "fluid_mass") > 0);
  CHECK(test::json_number(summary, "fluid_volume") > 0);

  auto profile = test::read_text(out / "profile.json");
  for (auto sys : {"neighbour_search", "wcsph_pair_forces", "density_gradient_renormalised",
                   "wall_boundary_adami", "integrate_leapfrog", "time_step_control", "output"})
    CHECK_MESSAGE(profile.find(std::string("\"name\": \"") + sys + "\"") != std::string::npos, sys);
  CHECK(test::read_text(out / "trace.json").find("\"ph\": \"X\"") != std::string::npos);

  auto probes = test::read_csv(out / "probes.csv");
  REQUIRE(probes.count("surge_front"));
  CHECK(probes["surge_front"].front() == doctest::Approx(0.25));  // block edge at t = 0
  CHECK(probes["time"].back() == doctest::Approx(0.02));
}

TEST_CASE("failure: a blow-up exits 3, names step, system and particle, and keeps whole frames") {
  auto out = test::scratch("failure_run");
  RunOptions opt;
  opt.scene = test::scene_path("dam_break_2d.toml");
  opt.out_dir = out.string();
  opt.quiet = true;
  // A fixed step 100 times the stable one: the column explodes within a few steps.
  opt.sets = {"particles.spacing=0.025", "time.dt=0.004", "output.interval=0.004"};
  CHECK(run_scene(opt) == kExitNumericalFailure);
  auto summary = test::read_text(out / "summary.json");
  CHECK(test::json_raw(summary, "status") == "failed");
  auto message = test::json_raw(summary, "message");
  CHECK(message.find("step ") == 0);
  CHECK(message.find("particle id ") != std::string::npos);
  CHECK(message.find("after system '") != std::string::npos);
  CHECK(count_files(out, ".tmp") == 0);
  // Every frame on disk opens and holds whole datasets.
  std::size_t frames = 0;
  for (auto& e : fs::directory_iterator(out / "frames")) {
    ++frames;
    auto dims = dataset_dims(e.path(), "position");
    CHECK(dims.size() == 2);
  }
  CHECK(frames >= 1);
  CHECK(test::read_text(out / "particles.xdmf").find("frame_00000.h5") != std::string::npos);
}

TEST_CASE("cli: exit codes and scene reference") {
  std::string bin = RYUSHI_BINARY;
  auto ok = test::run_command(bin + " check " + test::scene_path("dam_break_2d.toml"));
  CHECK(ok.code == 0);
  CHECK(ok.output.find("OK") != std::string::npos);
  CHECK(test::run_command(bin + " check " + test::scene_path("hydrostatic_2d.toml")).code == 0);
  CHECK(test::run_command(bin + " check " + test::scene_path("dam_break_3d.toml")).code == 0);
  // Every shipped scene loads and builds (a renamed key or a moved mesh file breaks none unseen).
  for (auto& e : std::filesystem::directory_iterator(test::source_dir() / "scenes")) {
    if (e.path().extension() != ".toml") continue;
    auto r = test::run_command(bin + " check " + e.path().string());
    CHECK_MESSAGE(r.code == 0, e.path().filename() << ": " << r.output);
  }
  auto bad_flag = test::run_command(bin + " run " + test::scene_path("dam_break_2d.toml") + " --threads zero");
  CHECK(bad_flag.code == 2);
  CHECK(bad_flag.output.find("ryushi: command line:") == 0);
  CHECK(test::run_command(bin + " frobnicate").code == 2);
  auto bad_set = test::run_command(bin + " check " + test::scene_path("dam_break_2d.toml") + " --set time.end=-1");
  CHECK(bad_set.code == 2);
  CHECK(bad_set.output == "ryushi: --set time.end=-1: 'end' in [time] is -1; it must be > 0\n");
  auto patch = test::run_command(bin + " patch-test --dim 2 --operator laplacian-sph2 --spacings 0.05 0.025");
  CHECK(patch.code == 0);
  CHECK(patch.output.find("rmse_interior") != std::string::npos);
  CHECK(patch.output.rfind("order_interior=") == patch.output.rfind('\n', patch.output.size() - 2) + 1);
  CHECK(test::run_command(bin + " patch-test --operator laplacian-magic").code == 2);
  // docs/scenes.md is exactly what the loader's schema says.
  auto keys = test::run_command(bin + " keys --markdown");
  CHECK(keys.code == 0);
  CHECK_MESSAGE(keys.output == test::read_text(test::source_dir() / "docs" / "scenes.md"),
                "docs/scenes.md is stale: run `make docs`");
}

namespace {
// No walls: the block falls out of the bottom of the domain.
const std::string kFallingBlock = test::block_scene("[0.3, 0.2]", "[0.7, 0.6]", 1.0, "[output]\ninterval = 0.05\n");
}  // namespace

TEST_CASE("failure: a particle leaving the domain names itself and the system that moved it") {
  auto dir = test::scratch("failure_domain");
  test::write_text(dir / "falling.toml", kFallingBlock);  // no walls: the block falls out
  RunOptions opt;
  opt.scene = (dir / "falling.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  CHECK(run_scene(opt) == kExitNumericalFailure);
  auto message = test::json_raw(test::read_text(dir / "out" / "summary.json"), "message");
  CHECK(message.find("left the domain") != std::string::npos);
  CHECK(message.find("after system 'integrate_leapfrog'") != std::string::npos);  // WCSPH's default
  // Free fall from y = 0.2 + d/2 reaches y < 0 after about sqrt(2 * 0.225 / g) = 0.21 s.
  auto time = test::json_number(test::read_text(dir / "out" / "summary.json"), "simulated_time");
  CHECK(std::abs(time / 0.214 - 1) < 0.05);  // relative (doctest's Approx adds 1 to its scale)
  CHECK(dataset_dims(dir / "out" / "frames" / "frame_00004.h5", "position").size() == 2);
}

TEST_CASE("failure: a collapsing time step stops the run with exit code 3") {
  auto dir = test::scratch("failure_dt");
  test::write_text(dir / "falling.toml", kFallingBlock);
  RunOptions opt;
  opt.scene = (dir / "falling.toml").string();
  opt.out_dir = (dir / "out").string();
  opt.quiet = true;
  opt.sets = {"time.dt_min=0.5"};  // every adaptive step is below this
  CHECK(run_scene(opt) == kExitNumericalFailure);
  auto message = test::json_raw(test::read_text(dir / "out" / "summary.json"), "message");
  CHECK(message.find("step 0 (t = 0 s): time step") == 0);
  CHECK(message.find("fell below time.dt_min = 0.5 s (system 'time_step_control')") != std::string::npos);
}
