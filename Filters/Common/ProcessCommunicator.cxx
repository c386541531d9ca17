// The MPI processes as the Core's Communicator: message sizes go round first (an all-gather of
// each process's byte counts), then every message as non-blocking sends and receives.
#include "ProcessCommunicator.h"

#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <stdexcept>

namespace parafluid::vtk
{
namespace
{
// One MPI message carries at most this many bytes (MPI counts are ints); longer ones are split.
constexpr std::size_t kChunk = std::size_t(1) << 30;
constexpr int kTag = 61061; // this communicator is private, so any tag is free

class ProcessCommunicator final : public parafluid::Communicator
{
public:
  explicit ProcessCommunicator(vtkSmartPointer<vtkMultiProcessController> controller)
    : Controller(std::move(controller))
    , Mpi(vtkMPICommunicator::SafeDownCast(this->Controller->GetCommunicator()))
  {
  }
  int rank() const override { return this->Controller->GetLocalProcessId(); }
  int size() const override { return this->Controller->GetNumberOfProcesses(); }
  std::vector<std::vector<std::uint8_t>> exchange(const std::vector<std::vector<std::uint8_t>>& sends) override;
  void reduce(std::vector<double>& values, parafluid::Reduction op) override;
  void abandon() override;

private:
  /// Every collective call begins with this all-gather of n counts a process (an exchange's
  /// message sizes, a reduction's zeros); a process that abandons sends -1s, and every process
  /// then throws ProcessFailure (with one exception: the one abandoning).
  std::vector<vtkIdType> gatherHeader(const std::vector<vtkIdType>& mine, bool abandoning);

  vtkSmartPointer<vtkMultiProcessController> Controller;
  vtkMPICommunicator* Mpi;
};

std::vector<std::vector<std::uint8_t>> ProcessCommunicator::exchange(
  const std::vector<std::vector<std::uint8_t>>& sends)
{
  const int n = this->size();
  const int me = this->rank();
  if (static_cast<int>(sends.size()) != n)
  {
    throw std::logic_error("ProcessCommunicator: exchange needs one message per process");
  }
  std::vector<vtkIdType> mine(static_cast<std::size_t>(n)), all(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
  {
    mine[static_cast<std::size_t>(r)] = static_cast<vtkIdType>(sends[static_cast<std::size_t>(r)].size());
  }
  all = this->gatherHeader(mine, false);
  std::vector<std::vector<std::uint8_t>> received(static_cast<std::size_t>(n));
  std::vector<vtkMPICommunicator::Request> requests;
  // Each message's chunks in order, receives posted before sends; a process's message to itself
  // is copied.
  auto chunks = [](std::size_t bytes) { return (bytes + kChunk - 1) / kChunk; };
  std::size_t count = 0;
  for (int r = 0; r < n; ++r)
  {
    if (r != me)
    {
      count += chunks(static_cast<std::size_t>(all[static_cast<std::size_t>(r) * n + me]));
      count += chunks(sends[static_cast<std::size_t>(r)].size());
    }
  }
  requests.resize(count);
  std::size_t next = 0;
  for (int r = 0; r < n; ++r)
  {
    auto& in = received[static_cast<std::size_t>(r)];
    if (r == me)
    {
      in = sends[static_cast<std::size_t>(r)];
      continue;
    }
    in.resize(static_cast<std::size_t>(all[static_cast<std::size_t>(r) * n + me]));
    for (std::size_t at = 0; at < in.size(); at += kChunk)
    {
      const int length = static_cast<int>(std::min(kChunk, in.size() - at));
      this->Mpi->NoBlockReceive(in.data() + at, length, r, kTag, requests[next++]);
    }
  }
  for (int r = 0; r < n; ++r)
  {
    const auto& out = sends[static_cast<std::size_t>(r)];
    if (r == me)
    {
      continue;
    }
    for (std::size_t at = 0; at < out.size(); at += kChunk)
    {
      const int length = static_cast<int>(std::min(kChunk, out.size() - at));
      this->Mpi->NoBlockSend(out.data() + at, length, r, kTag, requests[next++]);
    }
  }
  if (!requests.empty())
  {
    this->Mpi->WaitAll(static_cast<int>(requests.size()), requests.data());
  }
  return received;
}

std::vector<vtkIdType> ProcessCommunicator::gatherHeader(const std::vector<vtkIdType>& mine, bool abandoning)
{
  const int n = this->size();
  std::vector<vtkIdType> all(static_cast<std::size_t>(n) * n);
  this->Controller->AllGather(mine.data(), all.data(), n);
  for (int r = 0; r < n && !abandoning; ++r)
  {
    if (all[static_cast<std::size_t>(r) * n] < 0)
    {
      throw parafluid::ProcessFailure("process " + std::to_string(r) + " of " + std::to_string(n) + " failed");
    }
  }
  return all;
}

void ProcessCommunicator::abandon()
{
  this->gatherHeader(std::vector<vtkIdType>(static_cast<std::size_t>(this->size()), -1), true);
}

void ProcessCommunicator::reduce(std::vector<double>& values, parafluid::Reduction op)
{
  this->gatherHeader(std::vector<vtkIdType>(static_cast<std::size_t>(this->size()), 0), false);
  const int operation = op == parafluid::Reduction::Sum   ? vtkCommunicator::SUM_OP
                        : op == parafluid::Reduction::Min ? vtkCommunicator::MIN_OP
                                                          : vtkCommunicator::MAX_OP;
  std::vector<double> out(values.size());
  this->Controller->AllReduce(values.data(), out.data(), static_cast<vtkIdType>(values.size()), operation);
  values = std::move(out);
}
} // namespace

std::unique_ptr<parafluid::Communicator> makeProcessCommunicator()
{
  auto* global = vtkMPIController::SafeDownCast(vtkMultiProcessController::GetGlobalController());
  if (!global || global->GetNumberOfProcesses() < 2)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkMultiProcessController> own;
  own.TakeReference(global->PartitionController(0, global->GetLocalProcessId()));
  if (!own || !vtkMPICommunicator::SafeDownCast(own->GetCommunicator()))
  {
    throw std::runtime_error("ParaView's MPI controller could not make a private communicator");
  }
  return std::make_unique<ProcessCommunicator>(std::move(own));
}
} // namespace parafluid::vtk
