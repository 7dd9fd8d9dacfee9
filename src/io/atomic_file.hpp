#pragma once
// Whole-file writes: content goes to NAME.tmp, then is renamed over NAME, so a killed run never
// leaves a half-written file behind. A write that fails (a full disk, a size limit, an
// unwritable directory) removes the .tmp and throws OutputError naming the file and the reason;
// the file it would have replaced stays as it was.
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ryushi {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void write_text_atomic(const std::filesystem::path& path, const std::string& content);
void write_bytes_atomic(const std::filesystem::path& path, const void* data, std::size_t size);

}  // namespace ryushi
