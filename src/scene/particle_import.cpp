#include "scene/particle_import.hpp"

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "functions/csv_row.hpp"
#include "io/hdf5_read.hpp"

namespace ryushi {

namespace {

std::shared_ptr<const ImportedParticles> from_frame(const std::string& path, int dimension) {
  auto out = std::make_shared<ImportedParticles>();
  H5Handle file{-1, H5Fclose};
  H5E_BEGIN_TRY {
    file.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  }
  H5E_END_TRY;
  if (file.id < 0) throw ImportError(path + ": not an HDF5 file");
  std::vector<double> x, v, p, kind;
  std::vector<hsize_t> dims;
  for (const char* name : {"position", "velocity", "pressure", "kind"})
    if (H5Lexists(file.id, name, H5P_DEFAULT) <= 0)
      throw ImportError(path + ": not a ryushi frame (no dataset '" + name + "')");
  x = read_raw<double>(file.id, "position", H5T_NATIVE_DOUBLE, &dims);
  v = read_raw<double>(file.id, "velocity", H5T_NATIVE_DOUBLE);
  p = read_raw<double>(file.id, "pressure", H5T_NATIVE_DOUBLE);
  kind = read_raw<double>(file.id, "kind", H5T_NATIVE_DOUBLE);
  const std::size_t n = kind.size();
  if (dims.size() != 2 || dims[0] != n || dims[1] != 3 || v.size() != 3 * n || p.size() != n)
    throw ImportError(path + ": not a ryushi frame (position, velocity, pressure and kind disagree in size)");
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] != 0) continue;
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(x[3 * i + a]) || !std::isfinite(v[3 * i + a]) || !std::isfinite(p[i]))
        throw ImportError(path + ": particle " + std::to_string(i) +
                          "'s position, velocity or pressure is not a finite number");
    if (dimension == 2 && x[3 * i + 2] != 0)
      throw ImportError(path + ": a 3D frame (particle " + std::to_string(i) + " has z != 0) in a 2D scene");
    out->position.push_back({x[3 * i], x[3 * i + 1], x[3 * i + 2]});
    out->velocity.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
    out->pressure.push_back(p[i]);
  }
  if (out->position.empty()) throw ImportError(path + ": the frame holds no fluid particle");
  return out;
}

std::shared_ptr<const ImportedParticles> from_csv(const std::string& path, int dimension) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) throw ImportError(path + ": empty file");
  std::map<std::string, std::size_t> column;
  {
    std::stringstream header(line);
    std::size_t k = 0;
    for (std::string name; std::getline(header, name, ',');) {
      name.erase(0, name.find_first_not_of(" \t\r"));
      name.erase(name.find_last_not_of(" \t\r") + 1);
      column[name] = k++;
    }
  }
  const char* axes[] = {"x", "y", "z"};
  const char* speeds[] = {"u", "v", "w"};
  bool has_velocity = true;
  for (int a = 0; a < dimension; ++a) {
    if (!column.count(axes[a]))
      throw ImportError(path + ":1: the header has no column '" + axes[a] + "' (it names x, y" +
                        (dimension == 3 ? ", z" : "") + " and any of u, v" + (dimension == 3 ? ", w" : "") +
                        ", p)");
    has_velocity = has_velocity && column.count(speeds[a]);
  }
  const bool has_pressure = column.count("p") != 0;
  auto out = std::make_shared<ImportedParticles>();
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (csv_blank(line)) continue;
    std::vector<double> values;
    try {
      values = csv_numbers(line);
    } catch (const std::runtime_error& e) {
      throw ImportError(path + ":" + std::to_string(number) + ": " + e.what());
    }
    if (values.size() != column.size())
      throw ImportError(path + ":" + std::to_string(number) + ": " + std::to_string(values.size()) +
                        " values, the header has " + std::to_string(column.size()));
    std::array<double, 3> x{0, 0, 0}, v{0, 0, 0};
    for (int a = 0; a < dimension; ++a) {
      x[a] = values[column[axes[a]]];
      if (has_velocity) v[a] = values[column[speeds[a]]];
    }
    out->position.push_back(x);
    if (has_velocity) out->velocity.push_back(v);
    if (has_pressure) out->pressure.push_back(values[column["p"]]);
  }
  if (out->position.empty()) throw ImportError(path + ": no particle after the header");
  return out;
}

}  // namespace

std::shared_ptr<const ImportedParticles> import_particles(const std::string& path, int dimension) {
  if (!std::ifstream(path).good()) throw ImportError("cannot open " + path);
  const auto extension = std::filesystem::path(path).extension().string();
  if (extension == ".h5" || extension == ".hdf5") return from_frame(path, dimension);
  if (extension == ".csv") return from_csv(path, dimension);
  throw ImportError(path + ": import reads a ryushi frame (.h5) or a CSV (.csv)");
}

}  // namespace ryushi
