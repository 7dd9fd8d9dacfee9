#include "geometry/bed.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace ryushi {

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

Raster read_esri_ascii(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw RasterError(path.string() + ": cannot open the raster file");
  auto fail = [&](int line, const std::string& m) -> RasterError {
    return RasterError(path.string() + ":" + std::to_string(line) + ": " + m);
  };
  // Header: "key value" lines until the first line that starts with a number.
  std::map<std::string, std::pair<double, int>> header;  // key -> (value, line)
  std::string text;
  int line_no = 0;
  std::streampos data_start = in.tellg();
  int data_line = 1;
  while (true) {
    data_start = in.tellg();
    if (!std::getline(in, text)) break;
    ++line_no;
    std::istringstream ls(text);
    std::string key;
    if (!(ls >> key)) continue;  // blank line
    if (std::isdigit(static_cast<unsigned char>(key[0])) || key[0] == '-' || key[0] == '+' || key[0] == '.') {
      data_line = line_no;
      break;
    }
    double value;
    std::string rest;
    if (!(ls >> value)) throw fail(line_no, "header key '" + key + "' has no numeric value");
    if (ls >> rest) throw fail(line_no, "header line '" + text + "' has more than a key and a value");
    header[lower(key)] = {value, line_no};
  }
  auto need = [&](const char* key) -> double {
    auto it = header.find(key);
    if (it == header.end()) throw fail(line_no, std::string("missing header key '") + key + "'");
    return it->second.first;
  };
  Raster r;
  double nc = need("ncols"), nr = need("nrows");
  if (nc < 2 || nr < 2 || nc != std::floor(nc) || nr != std::floor(nr) || nc * nr > 1e8)
    throw fail(header["ncols"].second,
               "ncols and nrows must be integers >= 2 (bilinear interpolation needs 2x2 cells)");
  r.ncols = int(nc), r.nrows = int(nr);
  r.cell = need("cellsize");
  if (!(r.cell > 0)) throw fail(header["cellsize"].second, "cellsize must be positive");
  const bool corner_x = header.count("xllcorner"), corner_y = header.count("yllcorner");
  if (!corner_x && !header.count("xllcenter"))
    throw fail(line_no, "missing header key 'xllcorner' (or 'xllcenter')");
  if (!corner_y && !header.count("yllcenter"))
    throw fail(line_no, "missing header key 'yllcorner' (or 'yllcenter')");
  r.x0 = corner_x ? header["xllcorner"].first + 0.5 * r.cell : header["xllcenter"].first;
  r.y0 = corner_y ? header["yllcorner"].first + 0.5 * r.cell : header["yllcenter"].first;
  if (header.count("nodata_value")) r.has_nodata = true, r.nodata = header["nodata_value"].first;
  // Data: nrows lines of ncols numbers, north first.
  in.clear();
  in.seekg(data_start);
  r.z.assign(std::size_t(r.ncols) * r.nrows, 0.0);
  int row = 0;
  line_no = data_line - 1;
  while (std::getline(in, text)) {
    ++line_no;
    std::istringstream ls(text);
    std::vector<double> values;
    std::string word;
    while (ls >> word) {
      char* end = nullptr;
      double v = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0') throw fail(line_no, "'" + word + "' is not a number");
      if (!std::isfinite(v))
        throw fail(line_no, "non-finite elevation '" + word + "' (mark missing cells with NODATA_value)");
      values.push_back(v);
    }
    if (values.empty()) continue;
    if (row >= r.nrows) throw fail(line_no, "more than nrows = " + std::to_string(r.nrows) + " data rows");
    if (int(values.size()) != r.ncols)
      throw fail(line_no, "row " + std::to_string(row + 1) + " has " + std::to_string(values.size()) +
                              " values, ncols = " + std::to_string(r.ncols));
    const int south_row = r.nrows - 1 - row;
    for (int c = 0; c < r.ncols; ++c) {
      r.z[std::size_t(south_row) * r.ncols + c] = values[c];
      if (r.is_nodata(values[c])) ++r.nodata_cells;
    }
    ++row;
  }
  if (row != r.nrows)
    throw fail(line_no, "only " + std::to_string(row) + " data rows, nrows = " + std::to_string(r.nrows));
  // No-data cells are high ground: the highest valid elevation, so water runs up against them
  // as against a bank and never reads a made-up depth there.
  r.dry.assign(r.z.size(), 0);
  double highest = -std::numeric_limits<double>::infinity();
  for (double v : r.z)
    if (!r.is_nodata(v)) highest = std::max(highest, v);
  if (!std::isfinite(highest)) throw fail(line_no, "every cell is NODATA_value");
  for (std::size_t k = 0; k < r.z.size(); ++k)
    if (r.is_nodata(r.z[k])) r.z[k] = highest, r.dry[k] = 1;
  return r;
}

double Raster::elevation(double x, double y) const {
  double fx = std::clamp((x - x0) / cell, 0.0, double(ncols - 1));
  double fy = std::clamp((y - y0) / cell, 0.0, double(nrows - 1));
  int c = std::min(int(fx), ncols - 2), r = std::min(int(fy), nrows - 2);
  double tx = fx - c, ty = fy - r;
  double z00 = at(r, c), z01 = at(r, c + 1), z10 = at(r + 1, c), z11 = at(r + 1, c + 1);
  return (1 - ty) * ((1 - tx) * z00 + tx * z01) + ty * ((1 - tx) * z10 + tx * z11);
}

bool Raster::nodata_at(double x, double y) const {
  if (dry.empty()) return false;
  int c = std::clamp(int(std::floor((x - x0) / cell + 0.5)), 0, ncols - 1);
  int r = std::clamp(int(std::floor((y - y0) / cell + 0.5)), 0, nrows - 1);
  return dry[std::size_t(r) * ncols + c] != 0;
}

double Bed::elevation(double x, double y) const {
  double z = raster ? raster->elevation(x, y) : elevation_base;
  for (auto& h : humps) {
    double dx = x - h.centre[0], dy = y - h.centre[1];
    z += h.height * std::exp(-(dx * dx + dy * dy) / (h.width * h.width));
  }
  for (auto& r : ramps)
    if (x >= r.min[0] && x <= r.max[0] && y >= r.min[1] && y <= r.max[1])
      z += r.gradient[0] * (x - r.origin[0]) + r.gradient[1] * (y - r.origin[1]);
  return z;
}

}  // namespace ryushi
