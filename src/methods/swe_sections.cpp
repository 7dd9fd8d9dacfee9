// The shallow-water method's sections ([swe], [bed], [[bed_hump]], [[bed_ramp]], [splitting]) and
// its bed: a constant, an ESRI ASCII raster, humps and ramps (docs/swe.md). The method's
// read_sections hook (swe_spec.cpp); the schema has inserted their defaults.
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "methods/swe_spec.hpp"
#include "scene/load_common.hpp"
#include "scene/validator.hpp"

namespace ryushi {

void read_swe_sections(Scene& sc, const toml::table& root, Validator& val) {
  const std::string& path = sc.path;
  auto get = [&](const char* section, const char* key) { return root[section][key]; };
  auto& w = sc.swe;
  w.influence_ratio = *get("swe", "influence_ratio").value<double>();
  w.gravity = *get("swe", "gravity").value<double>();
  w.manning = *get("swe", "manning").value<double>();
  w.slip = *get("swe", "walls").value<std::string>() == "slip";
  w.edge_correction = *get("swe", "edge_correction").value<bool>();
  w.momentum = *get("swe", "momentum").value<std::string>();
  if (root["swe"]["ritter_dam_x"] || root["swe"]["ritter_depth"]) {
    if (!root["swe"]["ritter_dam_x"] || !root["swe"]["ritter_depth"])
      val.fail(root["swe"].node(), "swe.ritter_dam_x", "[swe] ritter_dam_x and ritter_depth go together");
    w.ritter_dam_x = *get("swe", "ritter_dam_x").value<double>();
    w.ritter_depth = *get("swe", "ritter_depth").value<double>();
  }
  w.splitting = *get("splitting", "enabled").value<bool>();
  w.split_area_ratio = *get("splitting", "area_ratio").value<double>();
  w.split_distance = *get("splitting", "distance").value<double>();
  w.split_along_gap = *get("splitting", "direction").value<std::string>() == "gap";
  w.max_particles = root["splitting"]["max_particles"].value_or(0LL);
  auto& bed = *w.bed;
  bed.elevation_base = *get("bed", "elevation").value<double>();
  if (auto raster = root["bed"]["raster"].value<std::string>()) {
    auto file = std::filesystem::path(*raster);
    if (file.is_relative()) file = std::filesystem::path(path).parent_path() / file;
    try {
      bed.raster = std::make_shared<Raster>(read_esri_ascii(file));
    } catch (const RasterError& e) {
      val.fail(root["bed"]["raster"].node(), "bed.raster", std::string("bed.raster: ") + e.what());
    }
    if (bed.raster->nodata_cells > 0)
      spdlog::info("{}: {} no-data cells of {} are dry high ground", file.string(), bed.raster->nodata_cells,
                   bed.raster->z.size());
  }
  auto xy = [&](const toml::node* n) {
    auto v = vec_of(*n);
    return std::array<double, 2>{v[0], v[1]};
  };
  if (auto* arr = root["bed_hump"].as_array())
    for (std::size_t i = 0; i < arr->size(); ++i)
      bed.humps.push_back({xy(root["bed_hump"][i]["centre"].node()),
                           *root["bed_hump"][i]["height"].value<double>(),
                           *root["bed_hump"][i]["width"].value<double>()});
  if (auto* arr = root["bed_ramp"].as_array())
    for (std::size_t i = 0; i < arr->size(); ++i) {
      auto r = root["bed_ramp"][i];
      bed.ramps.push_back(
          {xy(r["min"].node()), xy(r["max"].node()), xy(r["origin"].node()), xy(r["gradient"].node())});
    }
}

}  // namespace ryushi
