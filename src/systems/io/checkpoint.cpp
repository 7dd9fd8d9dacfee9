#include "systems/io/checkpoint.hpp"

#include <hdf5.h>

#include <sstream>
#include <stdexcept>

#include "io/hdf5_image.hpp"
#include "io/hdf5_read.hpp"

namespace ryushi {

namespace {

void write_raw(hid_t loc, const std::string& name, hid_t type, const void* data, std::vector<hsize_t> dims) {
  H5Handle space{H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose};
  H5Handle set{H5Dcreate2(loc, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose};
  if (set.id < 0) throw std::runtime_error("HDF5: cannot create " + name);
  if (!dims.empty() && dims[0] == 0) return;
  h5_check(H5Dwrite(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name);
}

void write_string(hid_t loc, const std::string& name, const std::string& text) {
  write_raw(loc, name, H5T_NATIVE_CHAR, text.data(), {text.size()});
}

std::string read_string(hid_t loc, const std::string& name) {
  auto bytes = read_raw<char>(loc, name, H5T_NATIVE_CHAR);
  return std::string(bytes.begin(), bytes.end());
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  if (s.empty()) return out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  return out;
}

const char* type_tag(ColumnType t) {
  switch (t) {
    case ColumnType::Scalar:
      return "scalar";
    case ColumnType::Vector:
      return "vector";
    case ColumnType::Tensor:
      return "tensor";
    case ColumnType::Flags:
      return "flags";
  }
  return "?";
}
ColumnType type_of_tag(const std::string& tag) {
  if (tag == "scalar") return ColumnType::Scalar;
  if (tag == "vector") return ColumnType::Vector;
  if (tag == "tensor") return ColumnType::Tensor;
  if (tag == "flags") return ColumnType::Flags;
  throw std::runtime_error("unknown column type '" + tag + "'");
}

// The clock as named doubles (long long values are exact in a double up to 2^53).
std::vector<std::pair<std::string, double*>> clock_fields(CheckpointClock& c, double& step, double& removed) {
  return {{"time", &c.time},
          {"dt", &c.dt},
          {"dt_chosen", &c.dt_chosen},
          {"next_output", &c.next_output},
          {"next_probe", &c.next_probe},
          {"next_checkpoint", &c.next_checkpoint},
          {"step", &step},
          {"initial_fluid_mass", &c.initial_fluid_mass},
          {"initial_fluid_volume", &c.initial_fluid_volume},
          {"removed", &removed},
          {"removed_mass", &c.removed_mass},
          {"wall_time_s", &c.wall_time_s},
          {"profile_step_total_s", &c.profile_step_total_s}};
}

}  // namespace

template <int D>
void write_checkpoint(const std::filesystem::path& path, const World<D>& world, const Checkpoint& c) {
  {
    Hdf5Image image(path);
    const hid_t file = image.id();
    write_string(file, "format", "ryushi checkpoint 1");
    write_string(file, "version", c.scene.version);
    write_string(file, "scene_path", c.scene.path);
    write_string(file, "scene_text", c.scene.text);
    std::string overrides;
    for (auto& o : c.scene.overrides) overrides += o + "\n";
    write_string(file, "overrides", overrides);
    const long long dim = D;
    write_raw(file, "dimension", H5T_NATIVE_LLONG, &dim, {1});
    write_raw(file, "run_id", H5T_NATIVE_UINT64, &c.scene.run_id, {1});
    CheckpointClock clock = c.clock;
    double step = double(clock.step), removed = double(clock.removed);
    std::vector<double> values;
    std::string names;
    for (auto& [name, value] : clock_fields(clock, step, removed))
      values.push_back(*value), names += name + "\n";
    write_raw(file, "clock", H5T_NATIVE_DOUBLE, values.data(), {values.size()});
    write_string(file, "clock_names", names);
    // Frames written so far (the XDMF collection) and the probe rows.
    std::string files, fields;
    std::vector<double> times;
    std::vector<long long> counts;
    for (auto& f : c.frames) {
      files += f.file + "\n";
      times.push_back(f.time);
      counts.push_back((long long)f.particles);
      std::string line;
      for (auto& fi : f.fields) line += (line.empty() ? "" : ";") + fi.name + ":" + type_tag(fi.type);
      fields += line + "\n";
    }
    write_string(file, "frame_files", files);
    write_string(file, "frame_fields", fields);
    write_raw(file, "frame_times", H5T_NATIVE_DOUBLE, times.data(), {times.size()});
    write_raw(file, "frame_particles", H5T_NATIVE_LLONG, counts.data(), {counts.size()});
    const hsize_t cols = c.probe_rows.empty() ? 0 : c.probe_rows.front().size();
    std::vector<double> rows;
    for (auto& r : c.probe_rows) rows.insert(rows.end(), r.begin(), r.end());
    write_raw(file, "probe_rows", H5T_NATIVE_DOUBLE, rows.data(), {c.probe_rows.size(), cols});
    write_raw(file, "cell_order", H5T_NATIVE_UINT32, c.cell_order.data(), {c.cell_order.size()});
    std::string system_names;
    for (std::size_t k = 0; k < c.system_states.size(); ++k) {
      system_names += c.system_states[k].first + "\n";
      auto& st = c.system_states[k].second;
      write_raw(file, "system_state_" + std::to_string(k), H5T_NATIVE_DOUBLE, st.data(), {st.size()});
    }
    write_string(file, "system_names", system_names);
    write_raw(file, "monitor_state", H5T_NATIVE_DOUBLE, c.monitor_state.data(), {c.monitor_state.size()});
    std::string profile_names;
    std::vector<double> calls, totals;
    for (auto& e : c.profile) {
      profile_names += e.name + "\n";
      calls.push_back(double(e.calls));
      totals.push_back(e.total_s);
    }
    write_string(file, "profile_names", profile_names);
    write_raw(file, "profile_calls", H5T_NATIVE_DOUBLE, calls.data(), {calls.size()});
    write_raw(file, "profile_seconds", H5T_NATIVE_DOUBLE, totals.data(), {totals.size()});

    // Columns, exactly as in memory.
    H5Handle group{H5Gcreate2(file, "columns", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    const hsize_t n = world.size();
    std::string types;
    for (auto& name : world.column_names()) {
      const ColumnType t = world.column_type(name);
      types += name + ":" + type_tag(t) + "\n";
      switch (t) {
        case ColumnType::Scalar:
          write_raw(group.id, name, H5T_NATIVE_DOUBLE, world.column(Component<Scalar>{name}).data(), {n});
          break;
        case ColumnType::Vector:
          write_raw(group.id, name, H5T_NATIVE_DOUBLE, world.column(Component<Vector>{name}).data(),
                    {n, hsize_t(D)});
          break;
        case ColumnType::Tensor:
          write_raw(group.id, name, H5T_NATIVE_DOUBLE, world.column(Component<Tensor>{name}).data(),
                    {n, hsize_t(D), hsize_t(D)});
          break;
        case ColumnType::Flags:
          write_raw(group.id, name, H5T_NATIVE_INT32, world.column(Component<Flags>{name}).data(), {n});
          break;
      }
    }
    write_string(file, "column_types", types);
    const long long next_id = world.next_id();
    write_raw(file, "next_id", H5T_NATIVE_LLONG, &next_id, {1});
    group.close(group.id), group.id = -1;
    image.save();
  }
}

Checkpoint read_checkpoint_header(const std::filesystem::path& path) {
  H5Handle file{-1, H5Fclose};
  H5E_BEGIN_TRY {
    file.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  }
  H5E_END_TRY;
  if (file.id < 0) throw std::runtime_error(path.string() + ": cannot open the checkpoint");
  Checkpoint c;
  try {
    H5E_BEGIN_TRY {
      if (read_string(file.id, "format") != "ryushi checkpoint 1")
        throw std::runtime_error("not a ryushi checkpoint");
    }
    H5E_END_TRY;
    c.scene.version = read_string(file.id, "version");
    c.scene.path = read_string(file.id, "scene_path");
    c.scene.text = read_string(file.id, "scene_text");
    c.scene.overrides = split(read_string(file.id, "overrides"), '\n');
    c.scene.dimension = int(read_raw<long long>(file.id, "dimension", H5T_NATIVE_LLONG).at(0));
    if (H5Lexists(file.id, "run_id", H5P_DEFAULT) > 0)
      c.scene.run_id = read_raw<std::uint64_t>(file.id, "run_id", H5T_NATIVE_UINT64).at(0);
    auto values = read_raw<double>(file.id, "clock", H5T_NATIVE_DOUBLE);
    auto names = split(read_string(file.id, "clock_names"), '\n');
    double step = 0, removed = 0;
    auto fields = clock_fields(c.clock, step, removed);
    for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
      for (auto& [name, target] : fields)
        if (name == names[k]) *target = values[k];
    c.clock.step = (long long)step;
    c.clock.removed = (long long)removed;
    auto files = split(read_string(file.id, "frame_files"), '\n');
    auto frame_fields = split(read_string(file.id, "frame_fields"), '\n');
    auto times = read_raw<double>(file.id, "frame_times", H5T_NATIVE_DOUBLE);
    auto counts = read_raw<long long>(file.id, "frame_particles", H5T_NATIVE_LLONG);
    for (std::size_t k = 0; k < files.size(); ++k) {
      FrameRecord f{files[k], times.at(k), std::size_t(counts.at(k)), {}};
      if (k < frame_fields.size())
        for (auto& item : split(frame_fields[k], ';')) {
          auto colon = item.rfind(':');
          f.fields.push_back({item.substr(0, colon), type_of_tag(item.substr(colon + 1))});
        }
      c.frames.push_back(std::move(f));
    }
    c.cell_order = read_raw<std::uint32_t>(file.id, "cell_order", H5T_NATIVE_UINT32);
    auto system_names = split(read_string(file.id, "system_names"), '\n');
    for (std::size_t k = 0; k < system_names.size(); ++k)
      c.system_states.push_back(
          {system_names[k],
           read_raw<double>(file.id, "system_state_" + std::to_string(k), H5T_NATIVE_DOUBLE)});
    if (H5Lexists(file.id, "monitor_state", H5P_DEFAULT) > 0)
      c.monitor_state = read_raw<double>(file.id, "monitor_state", H5T_NATIVE_DOUBLE);
    if (H5Lexists(file.id, "profile_names", H5P_DEFAULT) > 0) {
      auto names = split(read_string(file.id, "profile_names"), '\n');
      auto calls = read_raw<double>(file.id, "profile_calls", H5T_NATIVE_DOUBLE);
      auto seconds = read_raw<double>(file.id, "profile_seconds", H5T_NATIVE_DOUBLE);
      for (std::size_t k = 0; k < names.size() && k < calls.size() && k < seconds.size(); ++k)
        c.profile.push_back({names[k], std::int64_t(calls[k]), seconds[k]});
    }
    std::vector<hsize_t> dims;
    auto rows = read_raw<double>(file.id, "probe_rows", H5T_NATIVE_DOUBLE, &dims);
    if (dims.size() == 2 && dims[1] > 0)
      for (hsize_t r = 0; r < dims[0]; ++r)
        c.probe_rows.emplace_back(rows.begin() + r * dims[1], rows.begin() + (r + 1) * dims[1]);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
  return c;
}

template <int D>
void restore_checkpoint_columns(const std::filesystem::path& path, World<D>& world) {
  H5Handle file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) throw std::runtime_error(path.string() + ": cannot open the checkpoint");
  H5Handle group{H5Gopen2(file.id, "columns", H5P_DEFAULT), H5Gclose};
  if (group.id < 0) throw std::runtime_error(path.string() + ": no columns");
  const auto id = read_raw<long long>(file.id, "next_id", H5T_NATIVE_LLONG).at(0);
  std::size_t n = 0;
  bool sized = false;
  auto entries = split(read_string(file.id, "column_types"), '\n');
  for (auto& entry : entries) {
    auto colon = entry.rfind(':');
    const std::string name = entry.substr(0, colon);
    const ColumnType t = type_of_tag(entry.substr(colon + 1));
    std::vector<hsize_t> dims;
    if (t == ColumnType::Flags) {
      auto data = read_raw<std::int32_t>(group.id, name, H5T_NATIVE_INT32, &dims);
      if (!sized) world.restore_size(dims.at(0), std::int32_t(id)), n = dims[0], sized = true;
      auto& col = world.ensure(Component<Flags>{name});
      col.assign(data.begin(), data.end());
      continue;
    }
    auto data = read_raw<double>(group.id, name, H5T_NATIVE_DOUBLE, &dims);
    if (!sized) world.restore_size(dims.at(0), std::int32_t(id)), n = dims[0], sized = true;
    if (dims.at(0) != n)
      throw std::runtime_error(path.string() + ": column '" + name + "' has the wrong length");
    const std::size_t per = t == ColumnType::Scalar ? 1 : t == ColumnType::Vector ? D : D * D;
    if (data.size() != n * per)
      throw std::runtime_error(path.string() + ": column '" + name + "' has the wrong shape");
    switch (t) {
      case ColumnType::Scalar:
        world.ensure(Component<Scalar>{name}).assign(data.begin(), data.end());
        break;
      case ColumnType::Vector: {
        auto& col = world.ensure(Component<Vector>{name});
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < D; ++a) col[i][a] = data[i * D + a];
        break;
      }
      case ColumnType::Tensor: {
        auto& col = world.ensure(Component<Tensor>{name});
        for (std::size_t i = 0; i < n; ++i)
          for (int a = 0; a < D * D; ++a) col[i].data()[a] = data[i * D * D + a];
        break;
      }
      case ColumnType::Flags:
        break;
    }
  }
  for (auto& name : world.column_names()) {
    bool found = false;
    for (auto& entry : entries) found |= entry.substr(0, entry.rfind(':')) == name;
    if (!found)
      throw std::runtime_error(path.string() + ": the pipeline's column '" + name +
                               "' is not in the checkpoint");
  }
}

template void write_checkpoint<2>(const std::filesystem::path&, const World<2>&, const Checkpoint&);
template void write_checkpoint<3>(const std::filesystem::path&, const World<3>&, const Checkpoint&);
template void restore_checkpoint_columns<2>(const std::filesystem::path&, World<2>&);
template void restore_checkpoint_columns<3>(const std::filesystem::path&, World<3>&);

}  // namespace ryushi
