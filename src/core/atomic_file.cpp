#include "pmdplan/core/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::string pattern = (dir / ("." + path.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0)
    throw std::runtime_error(path.string() + ": cannot create a temporary file: " + std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      ::unlink(pattern.c_str());
      throw std::runtime_error(path.string() + ": write failed: " + std::strerror(err));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const int err = errno;
    ::unlink(pattern.c_str());
    throw std::runtime_error(path.string() + ": write failed: " + std::strerror(err));
  }
  ::chmod(pattern.c_str(), 0644);
  if (std::rename(pattern.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(pattern.c_str());
    throw std::runtime_error(path.string() + ": cannot replace the file: " + std::strerror(err));
  }
}

std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace pmdplan
