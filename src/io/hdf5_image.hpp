#pragma once
// An HDF5 file built in memory (the core driver, no backing store) and written to disk in one
// piece by write_bytes_atomic. HDF5 itself never touches the disk: a full disk or a size limit
// is an OutputError naming the file, and the library is not left with a file it cannot close
// (HDF5 1.10 crashed at exit after a failed close).
#include <hdf5.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"

namespace ryushi {

// An HDF5 identifier closed with its own close function when it goes out of scope.
struct H5Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Handle() {
    if (id >= 0) close(id);
  }
};

inline void h5_check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

class Hdf5Image {
 public:
  explicit Hdf5Image(const std::filesystem::path& path) : path_(path) {
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fapl_core(fapl, 1 << 20, 0);
    id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    if (id_ < 0) throw std::runtime_error(path.string() + ": cannot create an HDF5 image in memory");
  }
  Hdf5Image(const Hdf5Image&) = delete;
  Hdf5Image& operator=(const Hdf5Image&) = delete;
  ~Hdf5Image() {
    if (id_ >= 0) H5Fclose(id_);
  }
  hid_t id() const { return id_; }

  // Writes the image to path_ (via path_.tmp and a rename).
  void save() {
    if (H5Fflush(id_, H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error(path_.string() + ": HDF5 flush failed");
    ssize_t size = H5Fget_file_image(id_, nullptr, 0);
    if (size < 0) throw std::runtime_error(path_.string() + ": HDF5 image size unknown");
    std::vector<char> bytes(static_cast<std::size_t>(size));
    if (H5Fget_file_image(id_, bytes.data(), bytes.size()) != size)
      throw std::runtime_error(path_.string() + ": HDF5 image incomplete");
    write_bytes_atomic(path_, bytes.data(), bytes.size());
  }

 private:
  std::filesystem::path path_;
  hid_t id_ = -1;
};

}  // namespace ryushi
