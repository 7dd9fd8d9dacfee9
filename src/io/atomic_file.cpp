#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

namespace ryushi {

namespace {
// POSIX writes, so the reason (ENOSPC, EFBIG, EACCES) reaches the message; SIGXFSZ is ignored
// once, so a file-size limit is an error return instead of a killed process.
void write_all(const std::filesystem::path& tmp, const char* data, std::size_t size) {
  static const bool ignore_xfsz = [] {
    std::signal(SIGXFSZ, SIG_IGN);
    return true;
  }();
  (void)ignore_xfsz;
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError(tmp.string() + ": cannot open for writing: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < size) {
    ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int e = n < 0 ? errno : ENOSPC;
      ::close(fd);
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw OutputError(tmp.string() + ": write failed: " + std::strerror(e));
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) {
    const int e = errno;
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw OutputError(tmp.string() + ": write failed: " + std::strerror(e));
  }
}
}  // namespace

void write_bytes_atomic(const std::filesystem::path& path, const void* data, std::size_t size) {
  auto tmp = path;
  tmp += ".tmp";
  write_all(tmp, static_cast<const char*>(data), size);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw OutputError(path.string() + ": cannot rename the finished file: " + ec.message());
}

void write_text_atomic(const std::filesystem::path& path, const std::string& content) {
  write_bytes_atomic(path, content.data(), content.size());
}

}  // namespace ryushi
