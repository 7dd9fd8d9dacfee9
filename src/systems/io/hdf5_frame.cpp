#include "systems/io/hdf5_frame.hpp"

#include <hdf5.h>

#include <cstdint>
#include <numeric>
#include <stdexcept>

#include "io/hdf5_image.hpp"

namespace ryushi {

std::vector<std::string> default_frame_fields() {
  return {"position", "velocity", "pressure", "density", "kind", "id"};
}

namespace {

template <class T>
void write_dataset(hid_t file, const std::string& name, hid_t type, const T* data,
                   std::vector<hsize_t> dims) {
  H5Handle space{H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose};
  H5Handle set{H5Dcreate2(file, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose};
  if (set.id < 0) throw std::runtime_error("HDF5: cannot create dataset " + name);
  h5_check(H5Dwrite(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name);
}

template <class T>
void write_attribute(hid_t file, const char* name, hid_t type, T value) {
  H5Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  H5Handle attr{H5Acreate2(file, name, type, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  h5_check(H5Awrite(attr.id, type, &value), std::string("writing attribute ") + name);
}

// Vectors and tensors as 3 and 3 x 3 components in every dimension (z = 0 in 2D): ParaView's
// glyphs, Calculator and tensor filters expect them so. Tensors row-major: [i][a][b] = M(a, b).
template <int D>
std::vector<double> padded_vectors(const std::vector<Vec<D>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int a = 0; a < D; ++a) out[3 * i + a] = v[i][a];
  return out;
}

template <int D>
std::vector<double> padded_tensors(const std::vector<Mat<D>>& m) {
  std::vector<double> out(9 * m.size(), 0.0);
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) out[9 * i + 3 * a + b] = m[i](a, b);
  return out;
}

}  // namespace

template <int D>
std::vector<FieldInfo> write_frame(const std::filesystem::path& path, const World<D>& world,
                                   const std::vector<std::string>& extra, double time, long long step,
                                   std::uint64_t run_id) {
  std::vector<FieldInfo> written;
  {
    Hdf5Image image(path);
    const hid_t file = image.id();
    const hsize_t n = world.size();
    auto fields = default_frame_fields();
    for (auto& e : extra)
      if (std::find(fields.begin(), fields.end(), e) == fields.end()) fields.push_back(e);
    for (auto& name : fields) {
      if (!world.has(name)) continue;  // e.g. velocity in a scene without fluid motion
      ColumnType t = world.column_type(name);
      switch (t) {
        case ColumnType::Scalar:
          write_dataset(file, name, H5T_NATIVE_DOUBLE, world.column(Component<Scalar>{name}).data(), {n});
          break;
        case ColumnType::Vector: {
          auto padded = padded_vectors<D>(world.column(Component<Vector>{name}));
          // A shallow-water scene is a plan view: its particles are drawn on the water surface,
          // at (x, y, z_s).
          if (D == 2 && name == "position" && world.has("surface_elevation")) {
            auto& zs = world.column(Component<Scalar>{"surface_elevation"});
            for (std::size_t i = 0; i < zs.size(); ++i) padded[3 * i + 2] = zs[i];
          }
          write_dataset(file, name, H5T_NATIVE_DOUBLE, padded.data(), {n, 3});
          break;
        }
        case ColumnType::Tensor: {
          auto padded = padded_tensors<D>(world.column(Component<Tensor>{name}));
          write_dataset(file, name, H5T_NATIVE_DOUBLE, padded.data(), {n, 3, 3});
          break;
        }
        case ColumnType::Flags:
          write_dataset(file, name, H5T_NATIVE_INT32, world.column(Component<Flags>{name}).data(), {n});
          break;
      }
      written.push_back({name, t});
    }
    // One vertex cell per particle: the Xdmf3 readers build cells only from explicit
    // connectivity, and a grid without cells draws nothing.
    std::vector<std::int32_t> vertices(n);
    std::iota(vertices.begin(), vertices.end(), 0);
    write_dataset(file, "connectivity", H5T_NATIVE_INT32, vertices.data(), {n});
    write_attribute(file, "time", H5T_NATIVE_DOUBLE, time);
    write_attribute(file, "step", H5T_NATIVE_LLONG, step);
    if (run_id) write_attribute(file, "run_id", H5T_NATIVE_UINT64, run_id);
    image.save();
  }
  return written;
}

template std::vector<FieldInfo> write_frame<2>(const std::filesystem::path&, const World<2>&,
                                               const std::vector<std::string>&, double, long long,
                                               std::uint64_t);
template std::vector<FieldInfo> write_frame<3>(const std::filesystem::path&, const World<3>&,
                                               const std::vector<std::string>&, double, long long,
                                               std::uint64_t);

std::uint64_t frame_run_id(const std::filesystem::path& path) {
  std::uint64_t id = 0;
  hid_t file = -1;
  H5E_BEGIN_TRY {  // a file that is not HDF5 is an answer here, not an error stack on stderr
    file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file >= 0 && H5Aexists(file, "run_id") > 0) {
      const hid_t attr = H5Aopen(file, "run_id", H5P_DEFAULT);
      if (attr < 0 || H5Aread(attr, H5T_NATIVE_UINT64, &id) < 0) id = 0;
      if (attr >= 0) H5Aclose(attr);
    }
    if (file >= 0) H5Fclose(file);
  }
  H5E_END_TRY;
  if (file < 0) throw std::runtime_error(path.string() + ": cannot open the frame");
  return id;
}

}  // namespace ryushi
