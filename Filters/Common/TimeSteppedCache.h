#pragma once
// The state a time-aware simulation filter keeps between requests (SPH Step, Rain, Stable
// Fluids): the running simulation, the output time it has reached, what it started from (the
// MTimes of the inputs and of the filter's properties), and the outputs already made. Asked for
// an output it has made, the filter copies it; asked for a later time it continues the run; asked
// for an earlier one it has not kept, or after a change of inputs or properties, it restarts.
#include "parafluid/common/MemoryBudget.h"

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace parafluid::vtk
{
template<class Simulation, class Info = char>
class TimeSteppedCache
{
public:
  /// What a run started from: the MTimes of the inputs (0 for an absent one) and the filter's.
  using Key = std::vector<vtkMTimeType>;

  /// Drops the run and the kept outputs when `key` is not what they were made from.
  void follow(const Key& key)
  {
    if (key != this->StartedFrom)
    {
      this->reset();
      this->StartedFrom = key;
    }
  }
  /// The run, or null.
  Simulation* simulation() const { return this->Run.get(); }
  /// The output index the run has reached.
  long long outputIndex() const { return this->Index; }
  /// The run can go on to `target` (it has not passed it).
  bool canContinueTo(long long target) const { return this->Run && this->Index <= target; }
  /// A new run at output 0 (the kept outputs of the same key stay: they are the same run's).
  Simulation& start(std::unique_ptr<Simulation> run)
  {
    this->Run = std::move(run);
    this->Index = 0;
    return *this->Run;
  }
  /// The run reached output `index`.
  void reached(long long index) { this->Index = index; }
  /// Drops the run (an error, or an abort between output times), keeping the outputs made.
  void dropRun() { this->Run.reset(); }
  /// Forgets everything.
  void reset()
  {
    this->Run.reset();
    this->Index = 0;
    this->Kept.clear();
    this->KeptBytes = 0;
  }

  /// Keeps shallow copies of the outputs made at `index` and their information, within a budget
  /// (a sixteenth of the memory budget; the earliest kept outputs go first).
  void keep(long long index, const std::vector<vtkDataObject*>& outputs, const Info& info = {})
  {
    Entry entry;
    entry.info = info;
    for (vtkDataObject* output : outputs)
    {
      vtkSmartPointer<vtkDataObject> copy = vtkSmartPointer<vtkDataObject>::Take(output->NewInstance());
      copy->ShallowCopy(output);
      entry.bytes += static_cast<std::size_t>(copy->GetActualMemorySize()) * 1024;
      entry.outputs.push_back(copy);
    }
    const std::size_t limit = parafluid::memoryBudgetBytes() / 16;
    if (entry.bytes > limit)
    {
      return;
    }
    this->forget(index);
    while (!this->Kept.empty() && this->KeptBytes + entry.bytes > limit)
    {
      this->forget(this->Kept.begin()->first);
    }
    this->KeptBytes += entry.bytes;
    this->Kept.emplace(index, std::move(entry));
  }
  /// Copies the outputs kept at `index` into `outputs` and returns their information, or null
  /// when none are kept there.
  const Info* restore(long long index, const std::vector<vtkDataObject*>& outputs) const
  {
    const auto found = this->Kept.find(index);
    if (found == this->Kept.end() || found->second.outputs.size() != outputs.size())
    {
      return nullptr;
    }
    for (std::size_t k = 0; k < outputs.size(); ++k)
    {
      outputs[k]->ShallowCopy(found->second.outputs[k]);
    }
    return &found->second.info;
  }
  std::size_t keptOutputs() const { return this->Kept.size(); }

private:
  struct Entry
  {
    std::vector<vtkSmartPointer<vtkDataObject>> outputs;
    Info info{};
    std::size_t bytes = 0;
  };
  void forget(long long index)
  {
    const auto found = this->Kept.find(index);
    if (found != this->Kept.end())
    {
      this->KeptBytes -= found->second.bytes;
      this->Kept.erase(found);
    }
  }

  std::unique_ptr<Simulation> Run;
  long long Index = 0;
  Key StartedFrom;
  std::map<long long, Entry> Kept;
  std::size_t KeptBytes = 0;
};
} // namespace parafluid::vtk
