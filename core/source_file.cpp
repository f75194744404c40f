#include "core/source_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ncsim::core {
namespace {

const char* next_line(const char* p, const char* end) {
  const auto* nl =
      static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
  return nl == nullptr ? nullptr : nl + 1;
}

std::uint32_t saturate(std::size_t v) {
  return v > std::numeric_limits<std::uint32_t>::max() ? std::numeric_limits<std::uint32_t>::max()
                                                       : static_cast<std::uint32_t>(v);
}

std::string size_text(std::size_t bytes) {
  if (bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

std::string file_kind_text(unsigned st_mode) {
  const auto mode = static_cast<mode_t>(st_mode);
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a file";
}

SourceFile::SourceFile(std::string name, std::string text)
    : name_(std::move(name)), owned_(std::move(text)), size_(owned_.size()) {
  sparse_.push_back(0);
}

SourceFile::~SourceFile() {
  if (map_ != nullptr) ::munmap(const_cast<char*>(map_), size_);
}

SourceFile::SourceFile(SourceFile&& o) noexcept
    : name_(std::move(o.name_)),
      owned_(std::move(o.owned_)),
      map_(std::exchange(o.map_, nullptr)),
      size_(std::exchange(o.size_, 0)),
      sparse_(std::move(o.sparse_)),
      indexed_all_(o.indexed_all_),
      line_total_(o.line_total_) {}

SourceFile& SourceFile::operator=(SourceFile&& o) noexcept {
  if (this != &o) {
    if (map_ != nullptr) ::munmap(const_cast<char*>(map_), size_);
    name_ = std::move(o.name_);
    owned_ = std::move(o.owned_);
    map_ = std::exchange(o.map_, nullptr);
    size_ = std::exchange(o.size_, 0);
    sparse_ = std::move(o.sparse_);
    indexed_all_ = o.indexed_all_;
    line_total_ = o.line_total_;
  }
  return *this;
}

SourceFile SourceFile::load(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error("cannot open '" + path.string() + "': " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    const auto size = static_cast<std::size_t>(st.st_size);
    void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (p == MAP_FAILED) {
      throw std::runtime_error("cannot map '" + path.string() + "': " + std::strerror(errno));
    }
    ::madvise(p, size, MADV_SEQUENTIAL);
    SourceFile f(path.string(), std::string());
    f.map_ = static_cast<const char*>(p);
    f.size_ = size;
    return f;
  }
  ::close(fd);
  // Empty files, and what cannot be mapped: read as a stream.
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("cannot read '" + path.string() + "'");
  return SourceFile(path.string(), std::move(text));
}

SourceFile SourceFile::load_regular(const std::filesystem::path& path, std::size_t max_bytes) {
  // O_NONBLOCK: opening a pipe does not wait for its writer; the type is then checked on the
  // open descriptor (no window between a check and the open).
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw std::runtime_error(std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int e = errno;
    ::close(fd);
    throw std::runtime_error(std::strerror(e));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw std::runtime_error("not a regular file (" + file_kind_text(st.st_mode) + ")");
  }
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > max_bytes) {
    ::close(fd);
    throw std::runtime_error(std::to_string(size) + " bytes, above the limit of " +
                             size_text(max_bytes));
  }
  if (size == 0) return SourceFile(path.string(), std::string());
  void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  const int e = errno;
  ::close(fd);
  if (p == MAP_FAILED) throw std::runtime_error(std::string("cannot map: ") + std::strerror(e));
  ::madvise(p, size, MADV_SEQUENTIAL);
  SourceFile f(path.string(), std::string());
  f.map_ = static_cast<const char*>(p);
  f.size_ = size;
  return f;
}

void SourceFile::release_before(std::size_t offset) const {
  if (map_ == nullptr || offset <= kKeepBehind) return;
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t end = (offset - kKeepBehind) / page * page;
  if (end > 0) ::madvise(const_cast<char*>(map_), end, MADV_DONTNEED);
}

void SourceFile::index_to(std::uint32_t line, std::size_t offset) const {
  const char* const begin = data();
  const char* const end = begin + size_;
  const std::size_t entry = line == 0 ? 0 : (line - 1) / kLineStride;
  while (!indexed_all_ && sparse_.size() - 1 < entry && sparse_.back() <= offset) {
    const char* p = begin + sparse_.back();
    if (sparse_.size() % 64 == 0) release_before(sparse_.back());  // a long scan
    std::uint32_t k = 0;
    for (; k < kLineStride && p != nullptr; ++k)
      p = next_line(p, end);
    if (p == nullptr) {
      indexed_all_ = true;
      break;
    }
    sparse_.push_back(static_cast<std::size_t>(p - begin));
  }
}

std::size_t SourceFile::find_line(std::uint32_t line) const {
  index_to(line, size_);
  const std::size_t entry = (line - 1) / kLineStride;
  if (entry >= sparse_.size()) return size_ + 1;  // no such line
  const char* const begin = data();
  const char* const end = begin + size_;
  const char* p = begin + sparse_[entry];
  for (std::uint32_t k = (line - 1) % kLineStride; k > 0; --k) {
    p = next_line(p, end);
    if (p == nullptr) return size_ + 1;  // no such line
  }
  return static_cast<std::size_t>(p - begin);
}

SourceLoc SourceFile::loc_of(std::size_t offset) const {
  offset = std::min(offset, size_);
  index_to(std::numeric_limits<std::uint32_t>::max(), offset);
  const auto it = std::upper_bound(sparse_.begin(), sparse_.end(), offset);
  const auto entry = static_cast<std::size_t>(it - sparse_.begin()) - 1;
  const char* const begin = data();
  const char* const at = begin + offset;
  const char* line_begin = begin + sparse_[entry];
  std::size_t line = entry * kLineStride + 1;
  for (;;) {
    const char* next = next_line(line_begin, at);
    if (next == nullptr) break;
    line_begin = next;
    ++line;
  }
  return {saturate(line), saturate(static_cast<std::size_t>(at - line_begin) + 1)};
}

std::size_t SourceFile::line_start(std::uint32_t line) const {
  if (line == 0) return size_;
  return std::min(find_line(line), size_);
}

std::string_view SourceFile::line_text(std::uint32_t line) const {
  if (line == 0) return {};
  const std::size_t b = find_line(line);
  if (b > size_) return {};
  const char* const begin = data();
  const char* const end = begin + size_;
  const char* nl = next_line(begin + b, end);
  std::size_t e = nl == nullptr ? size_ : static_cast<std::size_t>(nl - begin) - 1;
  if (e > b && begin[e - 1] == '\r') --e;
  return {begin + b, e - b};
}

std::uint32_t SourceFile::line_count() const {
  if (line_total_ != 0) return line_total_;
  index_to(std::numeric_limits<std::uint32_t>::max(), size_);
  const char* const begin = data();
  const char* const end = begin + size_;
  const char* p = begin + sparse_.back();
  std::size_t lines = (sparse_.size() - 1) * kLineStride + 1;
  while ((p = next_line(p, end)) != nullptr)
    ++lines;
  line_total_ = saturate(lines);
  return line_total_;
}

}  // namespace ncsim::core
