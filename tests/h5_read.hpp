#pragma once
// Reads a frame's datasets back for the tests. A missing file or dataset fails the test
// (REQUIRE), so a check on its values cannot pass on nothing.
#include <doctest/doctest.h>
#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace ryushi::test {

struct Dataset {
  std::vector<double> values;  // row-major, converted to double
  std::vector<hsize_t> dims;
};

inline Dataset read_dataset(const std::filesystem::path& file, const std::string& name) {
  Dataset out;
  hid_t f = -1, d = -1;
  H5E_BEGIN_TRY {
    f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f >= 0) d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  }
  H5E_END_TRY;
  if (d < 0 && f >= 0) H5Fclose(f);
  REQUIRE_MESSAGE(f >= 0, "cannot open " << file);
  REQUIRE_MESSAGE(d >= 0, "no dataset '" << name << "' in " << file);
  hid_t s = H5Dget_space(d);
  out.dims.resize(H5Sget_simple_extent_ndims(s));
  H5Sget_simple_extent_dims(s, out.dims.data(), nullptr);
  out.values.resize(H5Sget_simple_extent_npoints(s));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return out;
}

// Frame k of a run: RUN/frames/frame_NNNNN.h5 (five digits, as the output writes them).
inline std::filesystem::path frame_path(const std::filesystem::path& run, int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.h5", k);
  return run / "frames" / name;
}

// The last frame of a run (frames/frame_NNNNN.h5, the highest number).
inline std::filesystem::path last_frame(const std::filesystem::path& run) {
  std::filesystem::path last;
  for (auto& e : std::filesystem::directory_iterator(run / "frames"))
    if (e.path().extension() == ".h5" && e.path() > last) last = e.path();
  REQUIRE_MESSAGE(!last.empty(), "no frame in " << run);
  return last;
}

// Fluid particles (kind 0) of a 3D frame, and how many of them have their centre outside the box
// [lo - margin, hi + margin] on every axis but the open top (the last axis has no upper bound).
struct Containment {
  std::size_t fluid = 0, outside = 0;
};
inline Containment fluid_containment(const std::filesystem::path& frame, const std::vector<double>& lo,
                                     const std::vector<double>& hi, double margin) {
  auto kind = read_dataset(frame, "kind").values, x = read_dataset(frame, "position").values;
  const std::size_t D = lo.size();
  Containment c;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    if (kind[i] != 0) continue;
    ++c.fluid;
    for (std::size_t a = 0; a < D; ++a)
      if (x[3 * i + a] < lo[a] - margin || (a + 1 < D && x[3 * i + a] > hi[a] + margin)) {
        ++c.outside;
        break;
      }
  }
  return c;
}

}  // namespace ryushi::test
