// The child process an assimp read is fenced in (assimp_fence.hpp says why and what the child
// may touch). The parent waits on a pidfd with the wall-clock limit and kills the child past
// it; the child limits its own address space, file sizes, processor time and core files before
// it reads, and says it finished by writing one byte to a pipe, so that success is known even
// where the host program has SIGCHLD ignored (then no exit status can be collected).
#include "import/assimp_fence.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <thread>
#include <utility>

#include "facet/error.hpp"

namespace facet::io {
namespace {

// The child's exit status when an allocation failed under its memory limit. assimp catches
// std::bad_alloc and reports it as an ordinary read error, after which the caller's own read (no
// dump came back) would make the same allocation without a limit: the child's new-handler exits
// with this instead.
constexpr int kOutOfMemoryExit = 97;
constexpr int kParentGoneExit = 98;

class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  int get() const { return fd_; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

enum class Fault { none, crash, abort, hang, memory, stall };

Fault test_fault() {
  const char* value = std::getenv("FACET_FENCE_TEST_FAULT");
  const std::string fault = value ? value : "";
  return fault == "crash"    ? Fault::crash
         : fault == "abort"  ? Fault::abort
         : fault == "hang"   ? Fault::hang
         : fault == "memory" ? Fault::memory
         : fault == "stall"  ? Fault::stall
                             : Fault::none;
}

std::uint64_t memory_budget(const ImportOptions& options) {
  if (options.import_memory_limit_bytes > 0) return options.import_memory_limit_bytes;
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 0;  // unknown: no limit
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size) / 2;
}

// This process's address space now, in bytes. The child starts with a copy of it (oneTBB and a
// Python interpreter reserve gigabytes they never touch), so its limit is this plus the budget.
std::uint64_t address_space_now() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (!statm) return 0;
  unsigned long long pages = 0;
  const int got = std::fscanf(statm, "%llu", &pages);
  std::fclose(statm);
  return got == 1 ? pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) : 0;
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

struct Limits {
  double seconds = 0.0;             // <= 0: none
  std::uint64_t address_space = 0;  // RLIMIT_AS; 0: none
  std::uint64_t budget = 0;         // what the caller allowed beyond the parent's own size
};

[[noreturn]] void exit_out_of_memory() { ::_exit(kOutOfMemoryExit); }

// FACET_FENCE_TEST_FAULT's failures, made in the child instead of a read's.
void make_fault(Fault fault, const Limits& limits) {
  switch (fault) {
    case Fault::none:
      return;
    case Fault::crash:
      ::raise(SIGSEGV);
      return;
    case Fault::abort: {
      static const char message[] = "assimp: code/Test.cpp:1: fenced: Assertion `probe' failed.\n";
      [[maybe_unused]] auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
      std::abort();
    }
    case Fault::hang:
      for (volatile std::uint64_t spin = 0;;) spin = spin + 1;
    case Fault::stall:  // asleep for good, as on a lock no thread of the child will release
      for (;;) ::pause();
    case Fault::memory: {
      const std::uint64_t size = std::max<std::uint64_t>(limits.budget, 1) * 2;
      auto* volatile block = new char[static_cast<std::size_t>(size)];
      block[0] = 1;
      return;
    }
  }
}

// The child, from fork() to _exit(): nothing here may wait for another thread. Never returns,
// and never unwinds into the caller's frames (an exception there would run the parent's code
// in the child).
[[noreturn]] void run_child(pid_t parent, const Limits& limits, int log_fd, int done_fd,
                            int result_fd, Fault fault,
                            const std::function<void(int)>& read) noexcept {
  // The child goes when the thread that forked it goes (the parent killed meanwhile).
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(kParentGoneExit);
  // What assimp prints (an assertion's message) goes to the log the parent reads.
  ::dup2(log_fd, STDOUT_FILENO);
  ::dup2(log_fd, STDERR_FILENO);
  // A crash is a crash: the host's handlers (Python's faulthandler, a viewer's) stay out of
  // the child, and no signal stays blocked.
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP, SIGXCPU})
    ::signal(sig, SIG_DFL);
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (limits.address_space > 0) {
    const rlimit space{limits.address_space, limits.address_space};
    ::setrlimit(RLIMIT_AS, &space);
  }
  if (limits.budget > 0) {
    // What the read writes to memory files is outside its address space: limited alike (a
    // write past the limit fails, and no whole result comes back).
    const rlimit size{limits.budget, limits.budget};
    ::setrlimit(RLIMIT_FSIZE, &size);
    ::signal(SIGXFSZ, SIG_IGN);
  }
  if (limits.seconds > 0.0) {
    const auto cpu = static_cast<rlim_t>(std::ceil(limits.seconds)) + 1;
    const rlimit processor{cpu, cpu + 1};  // SIGXCPU at the soft limit, SIGKILL at the hard
    ::setrlimit(RLIMIT_CPU, &processor);
  }
  std::set_new_handler(exit_out_of_memory);
  try {
    make_fault(fault, limits);
    read(result_fd);
  } catch (const std::bad_alloc&) {
    // Where operator new is replaced by one that throws without asking the new-handler (a
    // host's counting allocator), or the read found assimp's failed for want of memory.
    ::_exit(kOutOfMemoryExit);
  } catch (...) {
    // Any other error the read threw is the caller's to find again.
  }
  const char done = 1;
  [[maybe_unused]] auto written = ::write(done_fd, &done, 1);
  ::_exit(0);
}

// A child that sleeps and has used no more processor time for this long is stalled: a read
// never sleeps (a disk wait is another state), but a child forked while another thread of the
// parent held a lock its allocator needs (one without fork handlers, as AddressSanitizer's)
// waits for it for ever.
constexpr double kStallSeconds = 2.0;

// A sanitizer's allocator may also wait on its lock spinning: a child forked while another
// thread held it then runs (yielding) for ever instead of sleeping, which only the time limit
// ends (a 60 s limit reading a tiny OBJ in CI's AddressSanitizer run). In a sanitized build a
// child that timed out is started again too.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kLocksSpinAcrossFork = true;
#else
constexpr bool kLocksSpinAcrossFork = false;
#endif

// The child's state letter and processor time in clock ticks (/proc/PID/stat), or false.
bool child_progress(pid_t pid, char& state, unsigned long long& ticks) {
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(pid));
  std::FILE* stat = std::fopen(path, "r");
  if (!stat) return false;
  char text[1024];
  const std::size_t got = std::fread(text, 1, sizeof text - 1, stat);
  std::fclose(stat);
  text[got] = '\0';
  // "pid (comm) state ppid ... utime stime": comm may hold spaces and parentheses.
  const char* after = std::strrchr(text, ')');
  unsigned long long user = 0, system = 0;
  if (!after || std::sscanf(after + 1, " %c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu",
                            &state, &user, &system) != 3) {
    return false;
  }
  ticks = user + system;
  return true;
}

enum class Outcome { ended, timed_out, stalled };

// Waits for the child to end, at most `seconds` (<= 0: for ever), watching that it makes
// progress. ended: with its status (-1 when it could not be collected: SIGCHLD ignored).
Outcome wait_for(pid_t pid, double seconds, int& status) {
  using Clock = std::chrono::steady_clock;
  const bool limited = seconds > 0.0;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(limited ? seconds : 0.0));
  auto remaining_ms = [&] {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    return std::max<long long>(left.count(), 0);
  };
  auto collect = [&](int options) {
    for (;;) {
      const pid_t got = ::waitpid(pid, &status, options);
      if (got == pid) return true;
      if (got == 0) return false;  // WNOHANG: still running
      if (errno == EINTR) continue;
      status = -1;  // ECHILD: reaped by the system (SIGCHLD ignored)
      return true;
    }
  };
  // Progress is looked at every slice; the child stalls once asleep with the same processor
  // time for kStallSeconds.
  constexpr int kSliceMs = 250;
  unsigned long long last_ticks = ~0ull;
  auto still_since = Clock::now();
  auto stalled = [&] {
    char state = 0;
    unsigned long long ticks = 0;
    if (!child_progress(pid, state, ticks) || state != 'S' || ticks != last_ticks) {
      last_ticks = ticks;
      still_since = Clock::now();
      return false;
    }
    return std::chrono::duration<double>(Clock::now() - still_since).count() >= kStallSeconds;
  };
#ifdef SYS_pidfd_open
  const Fd pidfd(static_cast<int>(::syscall(SYS_pidfd_open, pid, 0)));
  if (pidfd.get() >= 0) {
    pollfd ready{pidfd.get(), POLLIN, 0};
    for (;;) {
      const long long wait_ms = limited ? std::min<long long>(remaining_ms(), kSliceMs) : kSliceMs;
      const int got = ::poll(&ready, 1, static_cast<int>(wait_ms));
      if (got > 0) return collect(0) ? Outcome::ended : Outcome::timed_out;
      if (got < 0 && errno != EINTR) break;  // fall back to polling waitpid
      if (limited && remaining_ms() == 0) return Outcome::timed_out;
      if (stalled()) return Outcome::stalled;
    }
  }
#endif
  for (auto pause = std::chrono::milliseconds(1);;
       pause = std::min(pause * 2, decltype(pause)(20))) {
    if (collect(WNOHANG)) return Outcome::ended;
    if (limited && remaining_ms() == 0) return Outcome::timed_out;
    if (stalled()) return Outcome::stalled;
    std::this_thread::sleep_for(pause);
  }
}

// The last line the child printed (an assertion's message), cut to a reasonable length; empty
// when it printed nothing.
std::string last_printed_line(int log_fd) {
  const off_t size = ::lseek(log_fd, 0, SEEK_END);
  if (size <= 0) return {};
  const off_t from = std::max<off_t>(0, size - 4096);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  const ssize_t got = ::pread(log_fd, text.data(), text.size(), from);
  text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  const std::size_t start = text.find_last_of("\r\n");
  if (start != std::string::npos) text.erase(0, start + 1);
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  if (text.size() > 200) text = text.substr(0, 197) + "...";
  return text;
}

// What ended the child, as the rest of "<path>: cannot import: ...".
std::string what_happened(int status, const Limits& limits, int log_fd) {
  const std::string said = last_printed_line(log_fd);
  const std::string saying = said.empty() ? "" : ": " + said;
  if (status == -1) return "assimp's reader ended without finishing (its exit status is lost)";
  if (WIFEXITED(status)) {
    if (WEXITSTATUS(status) == kOutOfMemoryExit) {
      return "assimp needed more than " + std::to_string(limits.budget >> 20) +
             " MiB of memory reading it (the limit: ImportOptions::import_memory_limit_bytes)";
    }
    return "assimp's reader exited with status " + std::to_string(WEXITSTATUS(status)) + saying;
  }
  const int sig = WTERMSIG(status);
  const char* name = ::sigdescr_np(sig);
  const std::string signal_text =
      "signal " + std::to_string(sig) + (name ? std::string(", ") + name : std::string());
  if (sig == SIGXCPU) {
    return "assimp used more than " + seconds_text(std::ceil(limits.seconds) + 1) +
           " s of processor time reading it and was stopped";
  }
  if (sig == SIGABRT) return "assimp aborted (" + signal_text + ") reading it" + saying;
  if (sig == SIGKILL) {
    return "assimp was killed (" + signal_text +
           ") reading it: out of memory, or past its processor time limit";
  }
  return "assimp crashed (" + signal_text + ") reading it" + saying;
}

}  // namespace

FencedResult::FencedResult(int fd) {
  struct stat about {};
  if (::fstat(fd, &about) != 0 || about.st_size <= 0) return;
  void* data =
      ::mmap(nullptr, static_cast<std::size_t>(about.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
  if (data == MAP_FAILED) return;
  data_ = data, size_ = static_cast<std::size_t>(about.st_size);
}

FencedResult::FencedResult(FencedResult&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

FencedResult& FencedResult::operator=(FencedResult&& other) noexcept {
  if (this != &other) {
    if (data_) ::munmap(data_, size_);
    data_ = std::exchange(other.data_, nullptr), size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

FencedResult::~FencedResult() {
  if (data_) ::munmap(data_, size_);
}

FencedResult run_fenced(const std::string& path, const ImportOptions& options,
                        const std::function<void(int)>& read) {
  if (!options.fence_assimp) return {};
  const Fault fault = test_fault();
  Limits limits;
  limits.seconds = options.import_time_limit_seconds;
  limits.budget = memory_budget(options);
  if (limits.budget > 0) limits.address_space = address_space_now() + limits.budget;
  // The child's output, read back only to quote an assertion's message.
  int log_fd = ::memfd_create("facet-assimp-log", MFD_CLOEXEC);
  if (log_fd < 0) log_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  const Fd log(log_fd);
  // A stalled child (wait_for) is started again: the lock it waited on is another thread's
  // for an instant.
  constexpr int kStarts = 3;
  for (int start = 1;; ++start) {
    // Non-blocking: a child another thread forks meanwhile may hold a copy of the write end.
    int done_pipe[2];
    if (::pipe2(done_pipe, O_CLOEXEC | O_NONBLOCK) != 0)
      throw Error(path +
                  ": cannot import: cannot start assimp's fenced reader: " + std::strerror(errno));
    const Fd done_read(done_pipe[0]);
    Fd done_write(done_pipe[1]);
    // What the read hands back, in memory (a new file for each start).
    const Fd result(::memfd_create("facet-assimp-result", MFD_CLOEXEC));
    if (result.get() < 0)
      throw Error(path +
                  ": cannot import: cannot start assimp's fenced reader: " + std::strerror(errno));
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
      throw Error(path +
                  ": cannot import: cannot start assimp's fenced reader: " + std::strerror(errno));
    }
    if (pid == 0) run_child(parent, limits, log.get(), done_write.get(), result.get(), fault, read);
    done_write.reset();
    int status = 0;
    const Outcome outcome = wait_for(pid, limits.seconds, status);
    if (outcome != Outcome::ended) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    if (outcome == Outcome::stalled && start < kStarts) continue;
    if (outcome == Outcome::timed_out && kLocksSpinAcrossFork && start < kStarts) continue;
    if (outcome == Outcome::stalled) {
      throw Error(path + ": cannot import: assimp's fenced reader stalled " +
                  std::to_string(kStarts) + " times (asleep, using no processor time)");
    }
    if (outcome == Outcome::timed_out) {
      throw Error(path + ": cannot import: assimp took longer than " +
                  seconds_text(limits.seconds) +
                  " s reading it and was stopped (the limit: --import-timeout, "
                  "ImportOptions::import_time_limit_seconds)");
    }
    char done = 0;
    const bool finished = ::read(done_read.get(), &done, 1) == 1;
    if (finished && (status == -1 || (WIFEXITED(status) && WEXITSTATUS(status) == 0)))
      return FencedResult(result.get());
    throw Error(path + ": cannot import: " + what_happened(status, limits, log.get()));
  }
}

}  // namespace facet::io
