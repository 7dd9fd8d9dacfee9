#pragma once
// Bed elevation z_b(x, y) of a shallow-water scene (plan view): a base that is either a constant
// or an ESRI ASCII grid (.asc, bilinear between cell centres), plus Gaussian humps, plus ramps
// (piecewise planes: inside its box a ramp adds gradient . (x - origin)). The method only needs
// z_b at particle positions: the momentum equation takes the gradient of the free surface
// z_s = h + z_b (well balanced: a lake at rest over any bed has a flat z_s and no force).
#include <array>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ryushi {

// A bad raster file: "file:line: message" (the loader turns it into exit code 2).
class RasterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// ESRI ASCII grid: ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter, cellsize and an
// optional NODATA_value, then nrows lines of ncols values, the northernmost (largest y) first.
struct Raster {
  int ncols = 0, nrows = 0;
  double x0 = 0, y0 = 0;  // centre of the south-west cell
  double cell = 1;
  bool has_nodata = false;
  double nodata = -9999;
  std::vector<double> z;  // row-major from the south: z[r * ncols + c], r = 0 the southernmost
  std::size_t nodata_cells = 0;
  std::vector<char> dry;  // 1 where the file said no-data (z there holds the highest valid value)

  double at(int r, int c) const { return z[std::size_t(r) * ncols + c]; }
  bool is_nodata(double v) const { return has_nodata && v == nodata; }
  // Bilinear between cell centres, clamped to the outer centres.
  double elevation(double x, double y) const;
  // Whether the cell that contains (x, y) was no-data in the file (no fluid starts there).
  bool nodata_at(double x, double y) const;
};

Raster read_esri_ascii(const std::filesystem::path& path);

struct BedHump {
  std::array<double, 2> centre{0, 0};
  double height = 0, width = 1;  // z += height exp(-|x - centre|^2 / width^2)
};
struct BedRamp {
  std::array<double, 2> min{0, 0}, max{0, 0}, origin{0, 0}, gradient{0, 0};
};

struct Bed {
  double elevation_base = 0;
  std::shared_ptr<const Raster> raster;  // replaces elevation_base where given
  std::vector<BedHump> humps;
  std::vector<BedRamp> ramps;

  double elevation(double x, double y) const;
};

}  // namespace ryushi
