#pragma once
// Whole-file writes: content goes to NAME.tmp, then is renamed over NAME, so a killed run never
// leaves a half-written file behind.
#include <filesystem>
#include <string>

namespace ryushi {

void write_text_atomic(const std::filesystem::path& path, const std::string& content);

}  // namespace ryushi
