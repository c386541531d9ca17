#pragma once
// The writer's temporary file beside its target ("<target>.tmp-<pid>"), made safe against the ways
// a write can stop: SIGTERM, SIGINT and SIGHUP remove it before the process ends (the handler
// then does what the signal did before: the default action, or the handler that was there);
// SIGKILL and power loss cannot be caught, so the next write to the same target removes the
// temporaries of processes that no longer run.
#include <string>

namespace parafluid::h5
{
std::string temporaryNameFor(const std::string& target);

/// Removes "<target>.tmp-<pid>" files whose process no longer runs; returns how many.
int removeStaleTemporaries(const std::string& target);

/// While alive, `path` is removed when the process is ended by SIGTERM, SIGINT or SIGHUP.
class TemporaryFileGuard
{
public:
  explicit TemporaryFileGuard(const std::string& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

private:
  int Slot = -1;
};
} // namespace parafluid::h5
