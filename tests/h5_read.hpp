#pragma once
// Reads a frame's datasets back for the tests. A missing file or dataset fails the test
// (REQUIRE), so a check on its values cannot pass on nothing.
#include <doctest/doctest.h>
#include <hdf5.h>

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

}  // namespace ryushi::test
