#include "ParallelH5PartStep.h"

#include "parafluid/common/Communicator.h"

#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkFieldData.h"
#include "vtkMPI.h"
#include "vtkMPICommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstring>
#include <map>

using parafluid::h5::Handle;

namespace parafluid::vtk
{
namespace
{
/// Rows per chunk, as the serial writer's: fast sequential reads, little decompressed per slice.
constexpr hsize_t kChunkRows = 65536;

/// One process's particle count and datasets (name, stored type, components), as bytes.
struct Signature
{
  std::uint64_t count = 0;
  struct Entry
  {
    std::string name;
    std::int32_t type = 0, components = 1;
  };
  std::vector<Entry> entries;

  std::vector<std::uint8_t> encode() const
  {
    std::vector<std::uint8_t> bytes(sizeof(count));
    std::memcpy(bytes.data(), &count, sizeof(count));
    for (const Entry& e : this->entries)
    {
      bytes.insert(bytes.end(), e.name.begin(), e.name.end());
      bytes.push_back(0);
      const std::int32_t numbers[2] = { e.type, e.components };
      const auto* p = reinterpret_cast<const std::uint8_t*>(numbers);
      bytes.insert(bytes.end(), p, p + sizeof(numbers));
    }
    return bytes;
  }

  static Signature decode(const std::vector<std::uint8_t>& bytes)
  {
    Signature s;
    if (bytes.size() < sizeof(s.count))
    {
      return s;
    }
    std::memcpy(&s.count, bytes.data(), sizeof(s.count));
    std::size_t at = sizeof(s.count);
    while (at < bytes.size())
    {
      Entry e;
      while (at < bytes.size() && bytes[at] != 0)
      {
        e.name.push_back(static_cast<char>(bytes[at++]));
      }
      ++at;
      std::int32_t numbers[2] = { 0, 1 };
      if (at + sizeof(numbers) > bytes.size())
      {
        break;
      }
      std::memcpy(numbers, bytes.data() + at, sizeof(numbers));
      at += sizeof(numbers);
      e.type = numbers[0];
      e.components = numbers[1];
      s.entries.push_back(std::move(e));
    }
    return s;
  }
};

/// `bytes` of this process on every process, indexed by rank.
std::vector<std::vector<std::uint8_t>> allGather(const std::vector<std::uint8_t>& bytes,
                                                 parafluid::Communicator& processes)
{
  return processes.exchange(std::vector<std::vector<std::uint8_t>>(static_cast<std::size_t>(processes.size()), bytes));
}

/// The lowest process with particles, or 0.
int sourceProcess(const std::vector<Signature>& all)
{
  for (std::size_t r = 0; r < all.size(); ++r)
  {
    if (all[r].count > 0)
    {
      return static_cast<int>(r);
    }
  }
  return 0;
}
} // namespace

bool parallelHdf5Available()
{
#ifdef H5_HAVE_PARALLEL
  return true;
#else
  return false;
#endif
}

Handle parallelFileAccess()
{
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#ifdef H5_HAVE_PARALLEL
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  auto* mpi = vtkMPICommunicator::SafeDownCast(controller ? controller->GetCommunicator() : nullptr);
  if (!mpi || !mpi->GetMPIComm() || !mpi->GetMPIComm()->GetHandle())
  {
    return Handle(-1, H5Pclose);
  }
  // HDF5 duplicates the communicator: its messages never meet ParaView's.
  H5Pset_fapl_mpio(access, *mpi->GetMPIComm()->GetHandle(), MPI_INFO_NULL);
  // The 1.8 file format at least, as the serial writer: long attributes go to dense storage.
  H5Pset_libver_bounds(access, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  return access;
#else
  return Handle(-1, H5Pclose);
#endif
}

std::string fromFirstProcess(const std::string& text, parafluid::Communicator& processes)
{
  std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(processes.size()));
  if (processes.rank() == 0)
  {
    for (auto& s : sends)
    {
      s.assign(text.begin(), text.end());
    }
  }
  const auto received = processes.exchange(sends);
  return std::string(received[0].begin(), received[0].end());
}

bool writeParallelStep(hid_t group, vtkPointSet* local, int compression, parafluid::Communicator& processes,
                       std::vector<std::string>& warnings, std::string& error)
{
  std::vector<H5PartColumn> mine;
  Signature signature;
  if (local && local->GetNumberOfPoints() > 0)
  {
    mine = h5partColumns(local, warnings);
    signature.count = static_cast<std::uint64_t>(local->GetNumberOfPoints());
    for (const H5PartColumn& c : mine)
    {
      signature.entries.push_back({ c.name, c.type, c.components });
    }
  }
  std::vector<Signature> all;
  for (const auto& bytes : allGather(signature.encode(), processes))
  {
    all.push_back(Signature::decode(bytes));
  }
  const int source = sourceProcess(all);
  hsize_t offset = 0, total = 0;
  for (std::size_t r = 0; r < all.size(); ++r)
  {
    offset += static_cast<int>(r) < processes.rank() ? all[r].count : 0;
    total += all[r].count;
  }
  // The datasets every process with particles has, in the source process's order and type; with
  // no particles anywhere, empty coordinates.
  std::vector<Signature::Entry> agreed;
  if (total == 0)
  {
    for (const char* axis : { "x", "y", "z" })
    {
      agreed.push_back({ axis, VTK_FLOAT, 1 });
    }
  }
  for (const Signature::Entry& e : total == 0 ? std::vector<Signature::Entry>{} : all[source].entries)
  {
    bool everywhere = true;
    for (const Signature& other : all)
    {
      everywhere =
        everywhere && (other.count == 0 || std::any_of(other.entries.begin(), other.entries.end(),
                                                       [&](const Signature::Entry& o)
                                                       { return o.name == e.name && o.components == e.components; }));
    }
    if (everywhere)
    {
      agreed.push_back(e);
    }
    else if (processes.rank() == 0)
    {
      warnings.push_back("point array '" + e.name + "' is not on every process's particles: not written");
    }
  }
  std::map<std::string, const H5PartColumn*> byName;
  for (const H5PartColumn& c : mine)
  {
    byName[c.name] = &c;
  }
  Handle transfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
#ifdef H5_HAVE_PARALLEL
  // Filtered (compressed) datasets are written in parallel only collectively.
  H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE);
#endif
  const hsize_t count = static_cast<hsize_t>(signature.count);
  bool ok = true;
  for (const Signature::Entry& e : agreed)
  {
    const auto components = static_cast<hsize_t>(e.components);
    const int rank = components == 1 ? 1 : 2;
    const hsize_t dims[2] = { total, components };
    Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
    Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (total > 0)
    {
      const hsize_t chunk[2] = { std::min(total, kChunkRows), components };
      H5Pset_chunk(properties, rank, chunk);
      if (compression > 0)
      {
        H5Pset_shuffle(properties);
        H5Pset_deflate(properties, static_cast<unsigned>(compression));
      }
    }
    // Collective: every process creates every dataset, with the same arguments.
    Handle dataset(
      H5Dcreate2(group, e.name.c_str(), h5partFileType(e.type), space, H5P_DEFAULT, properties, H5P_DEFAULT), H5Dclose);
    if (!dataset.valid())
    {
      error = "cannot create dataset '" + e.name + "'";
      ok = false;
      continue; // the others still create and write the rest
    }
    if (total == 0)
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> values;
    if (count > 0)
    {
      values = h5partValuesAs(byName.at(e.name)->values, e.type);
    }
    const hsize_t start[2] = { offset, 0 }, size[2] = { count, components };
    const hsize_t memoryDims[2] = { std::max<hsize_t>(count, 1), components };
    Handle memory(H5Screate_simple(rank, memoryDims, nullptr), H5Sclose);
    if (count > 0)
    {
      H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, size, nullptr);
    }
    else
    {
      H5Sselect_none(space);
      H5Sselect_none(memory);
    }
    const void* data = values ? values->GetVoidPointer(0) : nullptr;
    // A process without particles names the type the others write from: a conversion on one
    // process turns the collective write of a compressed dataset into an error.
    const hid_t memoryType = values ? h5partMemoryType(values) : h5partNativeType(e.type);
    if (H5Dwrite(dataset, memoryType, memory, space, transfer, data) < 0)
    {
      error = "failed writing '" + e.name + "'";
      ok = false;
    }
  }
  return ok;
}

vtkSmartPointer<vtkFieldData> agreedFieldData(vtkPointSet* local, parafluid::Communicator& processes)
{
  const std::uint64_t count = local ? static_cast<std::uint64_t>(local->GetNumberOfPoints()) : 0;
  std::vector<std::uint8_t> mine(sizeof(count));
  std::memcpy(mine.data(), &count, sizeof(count));
  std::vector<Signature> counts;
  for (const auto& bytes : allGather(mine, processes))
  {
    counts.push_back(Signature::decode(bytes));
  }
  const int source = sourceProcess(counts);
  std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(processes.size()));
  if (processes.rank() == source)
  {
    vtkNew<vtkPolyData> carrier;
    if (local)
    {
      carrier->GetFieldData()->ShallowCopy(local->GetFieldData());
    }
    vtkNew<vtkCharArray> buffer;
    vtkCommunicator::MarshalDataObject(carrier, buffer);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(buffer->GetPointer(0));
    for (auto& s : sends)
    {
      s.assign(bytes, bytes + buffer->GetNumberOfValues());
    }
  }
  const auto received = processes.exchange(sends);
  auto fields = vtkSmartPointer<vtkFieldData>::New();
  const auto& message = received[static_cast<std::size_t>(source)];
  if (!message.empty())
  {
    vtkNew<vtkCharArray> buffer;
    buffer->SetNumberOfValues(static_cast<vtkIdType>(message.size()));
    std::memcpy(buffer->GetPointer(0), message.data(), message.size());
    vtkSmartPointer<vtkDataObject> carrier = vtkCommunicator::UnMarshalDataObject(buffer);
    if (carrier)
    {
      fields->ShallowCopy(carrier->GetFieldData());
    }
  }
  return fields;
}
} // namespace parafluid::vtk
