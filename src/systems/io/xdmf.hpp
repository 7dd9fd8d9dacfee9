#pragma once
// particles.xdmf: a temporal collection pointing at every frame's HDF5 datasets, so ParaView
// opens the whole series as point data (one vertex cell per particle), in every ParaView reader.
#include <filesystem>
#include <string>
#include <vector>

#include "systems/io/hdf5_frame.hpp"

namespace ryushi {

struct FrameRecord {
  std::string file;  // relative to the output directory
  double time;
  std::size_t particles;
  std::vector<FieldInfo> fields;
};

std::string xdmf_document(const std::vector<FrameRecord>& frames);

}  // namespace ryushi
