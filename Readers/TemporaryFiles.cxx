#include "TemporaryFiles.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <mutex>
#include <unistd.h>

namespace parafluid::h5
{
namespace
{
// Fixed storage: a signal handler may only touch memory that is never reallocated.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
char SlotPaths[kSlots][kPathBytes];
// 0: free, 1: being filled, 2: a live temporary the handler removes.
std::atomic<int> SlotState[kSlots];
constexpr int kSignals[] = { SIGTERM, SIGINT, SIGHUP };
struct sigaction PreviousActions[3];
std::once_flag Installed;

void onSignal(int signal, siginfo_t* info, void* context)
{
  for (int k = 0; k < kSlots; ++k)
  {
    if (SlotState[k].load() == 2)
    {
      ::unlink(SlotPaths[k]);
    }
  }
  for (int s = 0; s < 3; ++s)
  {
    if (kSignals[s] != signal)
    {
      continue;
    }
    const struct sigaction& previous = PreviousActions[s];
    if (previous.sa_flags & SA_SIGINFO)
    {
      previous.sa_sigaction(signal, info, context);
    }
    else if (previous.sa_handler == SIG_DFL)
    {
      ::sigaction(signal, &previous, nullptr);
      ::raise(signal);
    }
    else if (previous.sa_handler != SIG_IGN)
    {
      previous.sa_handler(signal);
    }
  }
}

void install()
{
  for (int s = 0; s < 3; ++s)
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_sigaction = onSignal;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    ::sigaction(kSignals[s], nullptr, &PreviousActions[s]);
    // A signal the process ignores (nohup, a background job) does not end it: leave it ignored.
    if (!(PreviousActions[s].sa_flags & SA_SIGINFO) && PreviousActions[s].sa_handler == SIG_IGN)
    {
      continue;
    }
    ::sigaction(kSignals[s], &action, nullptr);
  }
}

std::string baseName(const std::string& path)
{
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string folderName(const std::string& path)
{
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}
} // namespace

std::string temporaryNameFor(const std::string& target)
{
  return target + ".tmp-" + std::to_string(::getpid());
}

int removeStaleTemporaries(const std::string& target)
{
  const std::string prefix = baseName(target) + ".tmp-";
  const std::string folder = folderName(target);
  DIR* directory = ::opendir(folder.c_str());
  if (!directory)
  {
    return 0;
  }
  int removed = 0;
  while (const dirent* entry = ::readdir(directory))
  {
    const std::string name = entry->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0)
    {
      continue;
    }
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
    if (end == name.c_str() + prefix.size() || *end != '\0' || pid <= 0 || pid == ::getpid())
    {
      continue;
    }
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH && ::unlink((folder + "/" + name).c_str()) == 0)
    {
      ++removed;
    }
  }
  ::closedir(directory);
  return removed;
}

TemporaryFileGuard::TemporaryFileGuard(const std::string& path)
{
  std::call_once(Installed, install);
  if (path.size() >= kPathBytes)
  {
    return;
  }
  for (int k = 0; k < kSlots; ++k)
  {
    // The path is complete before the slot turns live, so the handler never reads half of one.
    int expected = 0;
    if (SlotState[k].compare_exchange_strong(expected, 1))
    {
      std::memcpy(SlotPaths[k], path.c_str(), path.size() + 1);
      SlotState[k].store(2);
      this->Slot = k;
      return;
    }
  }
}

TemporaryFileGuard::~TemporaryFileGuard()
{
  if (this->Slot >= 0)
  {
    SlotState[this->Slot].store(0);
  }
}
} // namespace parafluid::h5
