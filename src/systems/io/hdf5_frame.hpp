#pragma once
// One output frame as an HDF5 file: a dataset per field (N; N x 3 for vectors and N x 3 x 3 for
// tensors in both dimensions, z components zero in 2D), `connectivity` (0..N-1, one vertex cell
// per particle for the XDMF readers), and `time` and `step` attributes on the root group.
// Written to NAME.tmp and renamed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ecs/world.hpp"

namespace ryushi {

struct FieldInfo {
  std::string name;
  ColumnType type;
};

// Fields always written, in this order, then the requested extras.
std::vector<std::string> default_frame_fields();

// run_id (0: none) marks the frame as the run's, as an attribute `run_id`: a resumed run checks
// that the frames it keeps are its own (app/run_checkpoint.hpp).
template <int D>
std::vector<FieldInfo> write_frame(const std::filesystem::path& path, const World<D>& world,
                                   const std::vector<std::string>& fields, double time, long long step,
                                   std::uint64_t run_id = 0);

// A frame's `run_id` attribute (0: it has none). Throws std::runtime_error when the file does not
// open as HDF5.
std::uint64_t frame_run_id(const std::filesystem::path& path);

}  // namespace ryushi
