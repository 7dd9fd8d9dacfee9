#pragma once
// Particles a scene starts from instead of (or besides) lattice blocks ([[import]]): the fluid
// particles of a ryushi frame (HDF5: position, velocity, pressure of kind 0), or a CSV of
// positions with optional fields (a header naming x, y[, z] and any of u, v[, w], p).
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ryushi {

class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImportedParticles {
  std::vector<std::array<double, 3>> position, velocity;  // velocity empty: at rest
  std::vector<double> pressure;                           // empty: the method's own start
};

// Throws ImportError naming the file (and for a CSV the line) and the problem.
std::shared_ptr<const ImportedParticles> import_particles(const std::string& path, int dimension);

}  // namespace ryushi
