// The rules for files an import opens (guarded_files.hpp): regular files only, opened without
// blocking, and references inside the model's folder unless allowed. POSIX calls rather than
// std::filesystem where the type must be checked on the open descriptor itself.
#include "import/guarded_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "facet/error.hpp"

namespace facet::io {
namespace {

namespace fs = std::filesystem;

std::string kind_of(mode_t mode) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "a special file";
}

// Whether `path` is `folder` or lies below it (both canonical).
bool inside(const fs::path& folder, const fs::path& path) {
  return std::mismatch(folder.begin(), folder.end(), path.begin(), path.end()).first ==
         folder.end();
}

fs::path canonical_or_empty(const fs::path& path) {
  std::error_code error;
  fs::path out = fs::canonical(path, error);
  return error ? fs::path() : out;
}

}  // namespace

std::string special_file_kind(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  return kind_of(st.st_mode);
}

void check_model_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) throw Error(path + ": no such file");
    throw Error(path + ": cannot be read (" + std::strerror(error) + ")");
  }
  const std::string kind = kind_of(st.st_mode);
  if (!kind.empty()) throw Error(path + ": is " + kind + ", not a model file");
}

ReferenceRules::ReferenceRules(const std::string& model_file, const ImportOptions& options)
    : model_path_(model_file), allow_outside_(options.allow_outside_paths) {
  fs::path folder = fs::path(model_file).parent_path();
  folder_ = canonical_or_empty(folder.empty() ? fs::path(".") : folder);
  model_ = canonical_or_empty(model_file);
}

std::string ReferenceRules::refusal(const fs::path& path) const {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};  // missing: the reader says so
  const std::string kind = kind_of(st.st_mode);
  if (!kind.empty()) return "is " + kind + ", not a file";
  if (allow_outside_) return {};
  const fs::path real = canonical_or_empty(path);
  if (real.empty()) return "cannot be resolved to a path inside the model's folder";
  if (real == model_ || (!folder_.empty() && inside(folder_, real))) return {};
  return "is outside the model's folder (it is " + real.string() +
         "): referenced files must stay inside " + folder_.string() +
         " unless outside paths are allowed (--allow-outside-paths)";
}

std::FILE* open_regular_file(const std::string& path, std::string& problem) {
  // Refused before opening where possible: opening some devices has effects of its own.
  const std::string kind = special_file_kind(path);
  if (!kind.empty()) {
    problem = "is " + kind + ", not a file";
    return nullptr;
  }
  // O_NONBLOCK: opening a named pipe swapped in since the check returns at once instead of
  // waiting for a writer; the type is then checked on what was really opened.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    problem = std::strerror(errno);
    return nullptr;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    problem = "is " + kind_of(st.st_mode) + ", not a file";
    ::close(fd);
    return nullptr;
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::FILE* file = ::fdopen(fd, "rb");
  if (!file) {
    problem = std::strerror(errno);
    ::close(fd);
  }
  return file;
}

std::string read_regular_file(const std::string& path) {
  std::string problem;
  std::FILE* file = open_regular_file(path, problem);
  if (!file)
    throw Error(path + ": " +
                (problem.rfind("is ", 0) == 0 ? problem : "cannot be read (" + problem + ")"));
  std::string bytes;
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) bytes.append(chunk, got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw Error(path + ": cannot be read");
  return bytes;
}

}  // namespace facet::io
