#include "util/checked_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/errors.h"

namespace phellem {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& step, int err) {
  throw UserError(path, "write", step + ": " + std::strerror(err));
}

}  // namespace

void write_file_checked(const std::string& path, const std::string& file, std::string_view bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd < 0) fail(path, "cannot create the file", errno);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      fail(path, "wrote " + std::to_string(done) + " of " + std::to_string(bytes.size()) + " bytes", err);
    }
    done += size_t(n);
  }
  // A full disk may show only here (delayed allocation); the file is renamed into place next.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int err = errno;
    ::close(fd);
    fail(path, "cannot flush the file to disk", err);
  }
  if (::close(fd) != 0 && errno != EINTR) fail(path, "cannot close the file", errno);
}

}  // namespace phellem
