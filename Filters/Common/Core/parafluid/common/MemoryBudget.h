#pragma once
// How much memory one output may take: half of the machine's physical memory, or half of the
// process's address-space limit (ulimit -v) when that is lower, or PARAFLUID_MEMORY_BUDGET_MB
// when set. Readers and filters check what a file or a parameter asks them to allocate against
// it and refuse with an error that says how much was asked, instead of aborting in the allocator
// or swapping the machine to a halt.
#include <cstddef>
#include <string>

namespace parafluid
{
std::size_t memoryBudgetBytes();

/// "1.5 GB", "320 MB": a byte count as a person reads it.
std::string describeBytes(double bytes);

/// Empty when `bytes` fits the budget; else a sentence naming `what` and both sizes.
std::string checkMemoryBudget(double bytes, const std::string& what);
} // namespace parafluid
