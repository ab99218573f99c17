// SPDX-License-Identifier: BSD-3-Clause
#include "WholeFile.h"

#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>

namespace meshsimp
{
namespace
{
/// A new, empty file beside path, opened for writing; -1 with errno set when none can be made.
int CreatePartFile(const std::string& path, std::string& partPath)
{
  static std::atomic<unsigned> counter{ 0 };
  const std::size_t slash = path.rfind('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = path.substr(folder.size());
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    partPath = folder + "." + name + "." + std::to_string(getpid()) + "." +
      std::to_string(counter++) + ".part";
    const int file = open(partPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (file >= 0 || errno != EEXIST)
    {
      return file;
    }
  }
  return -1;
}

/// The part file's bytes written, checked, flushed to the disk and closed; false with errno set
/// (an exception from write is a failure too, the file still closed).
bool Finish(std::FILE* out, const std::function<bool(std::FILE*)>& write)
{
  errno = 0;
  bool written = false;
  try
  {
    written = write(out);
  }
  catch (const std::exception&)
  {
    errno = errno != 0 ? errno : ENOMEM;
  }
  bool ok = written && !std::ferror(out) && std::fflush(out) == 0 && fsync(fileno(out)) == 0;
  const int failure = errno;
  ok = std::fclose(out) == 0 && ok;
  errno = failure != 0 ? failure : errno;
  return ok;
}
}

bool WriteWholeFile(
  const std::string& given, const std::function<bool(std::FILE*)>& write, std::string& error)
{
  // A link is written through: the part file goes beside the file it names, which it replaces.
  std::error_code ignored;
  const std::string path = std::filesystem::is_symlink(given, ignored) && std::filesystem::exists(given, ignored)
    ? std::filesystem::canonical(given, ignored).string()
    : given;
  std::string partPath;
  const int file = CreatePartFile(path, partPath);
  std::FILE* out = file >= 0 ? fdopen(file, "wb") : nullptr;
  if (!out)
  {
    error = std::strerror(errno);
    if (file >= 0)
    {
      close(file);
      unlink(partPath.c_str());
    }
    return false;
  }
  struct stat existing;
  if (stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode))
  {
    fchmod(file, existing.st_mode & 07777);
  }
  if (!Finish(out, write) || std::rename(partPath.c_str(), path.c_str()) != 0)
  {
    error = errno != 0 ? std::strerror(errno) : "the data could not be written";
    unlink(partPath.c_str());
    return false;
  }
  return true;
}

} // namespace meshsimp
