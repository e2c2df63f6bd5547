// assimp's file access held to facet's rules (guarded_io.hpp): paths checked against the
// model's ReferenceRules, files opened with open_regular_file, read through stdio.
#include "import/guarded_io.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <assimp/IOStream.hpp>
#include <cstdio>
#include <filesystem>

namespace facet::io {
namespace {

// A read-only stdio stream (assimp's DefaultIOStream cannot be made from outside).
class FileStream : public Assimp::IOStream {
 public:
  explicit FileStream(std::FILE* file) : file_(file) {}
  ~FileStream() override { std::fclose(file_); }

  size_t Read(void* buffer, size_t size, size_t count) override {
    return size == 0 || count == 0 ? 0 : std::fread(buffer, size, count, file_);
  }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const int whence = origin == aiOrigin_SET   ? SEEK_SET
                       : origin == aiOrigin_CUR ? SEEK_CUR
                                                : SEEK_END;
    return std::fseek(file_, static_cast<long>(offset), whence) == 0 ? aiReturn_SUCCESS
                                                                     : aiReturn_FAILURE;
  }
  size_t Tell() const override { return static_cast<size_t>(std::ftell(file_)); }
  size_t FileSize() const override {
    struct stat st {};
    return ::fstat(fileno(file_), &st) == 0 ? static_cast<size_t>(st.st_size) : 0;
  }
  void Flush() override {}

 private:
  std::FILE* file_;
};

}  // namespace

bool GuardedIOSystem::refused(const std::string& path, const std::string& problem) const {
  if (problem.empty()) return false;
  // One file under several spellings ("lib.mtl", "./lib.mtl": readers build paths their own
  // way) is one refusal.
  std::error_code error;
  std::string key = std::filesystem::absolute(path, error).lexically_normal().string();
  if (error) key = path;
  if (std::find(refused_paths_.begin(), refused_paths_.end(), key) == refused_paths_.end()) {
    refused_paths_.push_back(key);
    refusals_.push_back(rules_.model_path() + ": referenced file " + path + " " + problem);
  }
  return true;
}

bool GuardedIOSystem::Exists(const char* path) const {
  if (!path) return false;
  struct stat st {};
  if (::stat(path, &st) != 0) return false;
  return !refused(path, rules_.refusal(path));
}

Assimp::IOStream* GuardedIOSystem::Open(const char* path, const char* mode) {
  if (!path) return nullptr;
  // An import only reads; assimp never asks to write, and is not let to.
  if (!mode || std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;
  if (refused(path, rules_.refusal(path))) return nullptr;
  std::string problem;
  std::FILE* file = open_regular_file(path, problem);
  if (!file) {
    if (problem.rfind("is ", 0) == 0) refused(path, problem);  // became special since the check
    return nullptr;
  }
  return new FileStream(file);
}

void GuardedIOSystem::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace facet::io
