#pragma once
// Reading a dataset whole: the checkpoint's restore and the import of a frame's particles.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5_image.hpp"

namespace ryushi {

// A dataset's shape and contents as type T (HDF5 converts); std::runtime_error if it is missing.
template <class T>
std::vector<T> read_raw(hid_t loc, const std::string& name, hid_t type,
                        std::vector<hsize_t>* dims_out = nullptr) {
  H5Handle set{H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose};
  if (set.id < 0) throw std::runtime_error("no dataset '" + name + "'");
  H5Handle space{H5Dget_space(set.id), H5Sclose};
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space.id));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  hsize_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<T> out(n);
  if (n) h5_check(H5Dread(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "reading " + name);
  if (dims_out) *dims_out = dims;
  return out;
}

}  // namespace ryushi
