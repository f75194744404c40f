#include "core/output_file.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <utility>

#include "core/source_file.hpp"

namespace ncsim::core {
namespace {

namespace fs = std::filesystem;

// Signal cleanup. The handler may only use async-signal-safe calls and state that is
// complete whenever it reads it: a slot's path is written before its state becomes kArmed and
// is not changed while armed. This is process state by nature (a signal handler has no other),
// kept to this file.
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kBusy = 1, kArmed = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  std::array<char, kPathBytes> path{};
};
std::array<Slot, SignalCleanup::kSlots> g_slots;
std::atomic<bool> g_installed{false};
constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

void remove_temporaries(int sig) {
  for (Slot& s : g_slots) {
    if (s.state.load() == kArmed) ::unlink(s.path.data());
  }
  // Only now the default action: the signal (and the other cleanup signals, all in the
  // handler's mask) stays blocked until the handler returns, then the process ends as the
  // signal's default says. Not SA_RESETHAND: with it the kernel resets the action when it takes
  // the signal, before it blocks it for the handler, so a second copy in that window (timeout(1)
  // sends one to the child and one to its process group) would end the process by the default
  // action before the handler ran.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

void install_handlers() {
  bool expected = false;
  if (!g_installed.compare_exchange_strong(expected, true)) return;
  struct sigaction sa {};
  sa.sa_handler = remove_temporaries;
  sigemptyset(&sa.sa_mask);
  for (const int sig : kSignals)
    sigaddset(&sa.sa_mask, sig);
  sa.sa_flags = 0;
  for (const int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup
    ::sigaction(sig, &sa, nullptr);
  }
}

// Blocks the cleanup signals for its lifetime; the thread's signal mask is restored after, and
// a signal that came meanwhile is delivered then.
class BlockCleanupSignals {
 public:
  BlockCleanupSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (const int sig : kSignals)
      sigaddset(&set, sig);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockCleanupSignals() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  BlockCleanupSignals(const BlockCleanupSignals&) = delete;
  BlockCleanupSignals& operator=(const BlockCleanupSignals&) = delete;

 private:
  sigset_t old_;
};

std::string why_errno(int e) {
  return std::strerror(e);
}

// The final target of `path`: symbolic links followed (at most 40, as the kernel), relative
// links against their own folder. Empty with `why` on a loop.
fs::path follow_links(const fs::path& path, std::string& why) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) {
      why = "cannot read the link: " + ec.message();
      return {};
    }
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  why = "too many levels of symbolic links";
  return {};
}

}  // namespace

SignalCleanup::SignalCleanup(const fs::path& path) {
  const std::string& s = path.native();
  if (s.size() >= kPathBytes) return;
  install_handlers();
  for (int i = 0; i < kSlots; ++i) {
    Slot& slot = g_slots[static_cast<std::size_t>(i)];
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kBusy)) continue;
    std::memcpy(slot.path.data(), s.c_str(), s.size() + 1);
    slot.state.store(kArmed);
    slot_ = i;
    return;
  }
}

SignalCleanup::~SignalCleanup() {
  if (slot_ < 0) return;
  Slot& slot = g_slots[static_cast<std::size_t>(slot_)];
  slot.state.store(kBusy);
  slot.path[0] = '\0';
  slot.state.store(kFree);
}

std::variant<OutputFile, std::string> OutputFile::open(const fs::path& target) {
  if (target.empty()) return std::string("an output needs a file name (an empty name was given)");
  const std::string named = "cannot write '" + target.string() + "': ";
  std::string why;
  const fs::path resolved = follow_links(target, why);
  if (resolved.empty()) return named + why;
  OutputFile o;
  o.target_ = target;
  o.resolved_ = resolved;
  struct stat st {};
  const bool exists = ::stat(resolved.c_str(), &st) == 0;
  if (exists && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode))) {
    // A stream: written in place (opening a pipe waits for its reader, as any writer does).
    const int fd = ::open(resolved.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return named + why_errno(errno);
    o.file_ = ::fdopen(fd, "wb");
    if (o.file_ == nullptr) {
      ::close(fd);
      return named + why_errno(errno);
    }
    o.written_ = resolved;
    return o;
  }
  if (exists && !S_ISREG(st.st_mode)) {
    return named + "it is " + file_kind_text(st.st_mode) + ", not a file an output may replace";
  }
  const fs::path folder = resolved.has_parent_path() ? resolved.parent_path() : fs::path(".");
  struct stat dir {};
  if (::stat(folder.c_str(), &dir) != 0 || !S_ISDIR(dir.st_mode)) {
    return named + "its folder '" + folder.string() + "' does not exist";
  }
  std::string temp = (folder / resolved.filename()).string() + ".XXXXXX.tmp";
  int fd = -1;
  int create_errno = 0;
  {
    // The temporary file exists only with its cleanup armed: a signal between its creation and
    // the arming left it behind (now and then in tests/cli/robust_files_test.sh).
    const BlockCleanupSignals blocked;
    fd = ::mkostemps(temp.data(), 4, O_CLOEXEC);
    create_errno = errno;
    if (fd >= 0) {
      o.written_ = temp;
      o.cleanup_ = std::make_unique<SignalCleanup>(o.written_);
    }
  }
  if (fd < 0) {
    return named + "cannot create a file in its folder '" + folder.string() +
           "': " + why_errno(create_errno);
  }
  // The permissions a plain open would give (or the replaced file's), not mkstemp's 0600.
  mode_t mode = 0;
  if (exists) {
    mode = st.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  [[maybe_unused]] const int chmod_status = ::fchmod(fd, mode);  // mkstemp's 0600 otherwise
  o.file_ = ::fdopen(fd, "wb");
  if (o.file_ == nullptr) {
    const int e = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    return named + why_errno(e);
  }
  return o;
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : target_(std::move(other.target_)),
      resolved_(std::move(other.resolved_)),
      written_(std::move(other.written_)),
      file_(std::exchange(other.file_, nullptr)),
      write_errno_(other.write_errno_),
      cleanup_(std::move(other.cleanup_)) {}

OutputFile::~OutputFile() {
  discard();
}

bool OutputFile::write(std::string_view text) {
  if (file_ == nullptr) return false;
  if (write_errno_ != 0) return false;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    write_errno_ = errno != 0 ? errno : EIO;
    return false;
  }
  return true;
}

bool OutputFile::commit(std::string& why) {
  if (file_ == nullptr) {
    why = "cannot write '" + target_.string() + "': already closed";
    return false;
  }
  int e = write_errno_;
  if (std::fflush(file_) != 0 && e == 0) e = errno;
  if (std::ferror(file_) != 0 && e == 0) e = EIO;
  if (std::fclose(std::exchange(file_, nullptr)) != 0 && e == 0) e = errno;
  if (e != 0) {
    why = "cannot write '" + written_.string() + "': " + why_errno(e);
    if (!in_place()) ::unlink(written_.c_str());
    cleanup_.reset();
    return false;
  }
  if (in_place()) return true;
  if (::rename(written_.c_str(), resolved_.c_str()) != 0) {
    e = errno;
    why = "cannot rename '" + written_.string() + "' to '" + resolved_.string() +
          "': " + why_errno(e);
    ::unlink(written_.c_str());
    cleanup_.reset();
    return false;
  }
  cleanup_.reset();
  return true;
}

void OutputFile::discard() {
  if (file_ != nullptr) std::fclose(std::exchange(file_, nullptr));
  if (cleanup_) {
    ::unlink(written_.c_str());
    cleanup_.reset();
  }
}

void ignore_sigpipe() {
  std::signal(SIGPIPE, SIG_IGN);
}

}  // namespace ncsim::core
