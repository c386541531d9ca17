#include "DistributedStep.h"

#include "vtkAppendPolyData.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <type_traits>

namespace parafluid::vtk
{
bool agreeOnParameters(parafluid::sph::SPHParameters& parameters, int resolved, parafluid::Communicator& processes)
{
  static_assert(std::is_trivially_copyable_v<parafluid::sph::SPHParameters>, "the parameters travel as bytes");
  const int size = processes.size();
  std::vector<double> verdict = { resolved == 0 ? 1.0 : 0.0, resolved == 1 ? double(processes.rank()) : double(size) };
  std::vector<double> failed = { verdict[0] }, source = { verdict[1] };
  processes.reduce(failed, parafluid::Reduction::Max);
  processes.reduce(source, parafluid::Reduction::Min);
  if (failed[0] > 0.0 || source[0] >= size)
  {
    return false;
  }
  const int from = static_cast<int>(source[0]);
  std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(size));
  if (processes.rank() == from)
  {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(&parameters);
    for (auto& message : sends)
    {
      message.assign(bytes, bytes + sizeof(parameters));
    }
  }
  const auto received = processes.exchange(sends);
  std::memcpy(&parameters, received[static_cast<std::size_t>(from)].data(), sizeof(parameters));
  return true;
}

vtkSmartPointer<vtkDataObject> boundaryOnEveryProcess(vtkDataObject* local)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!local || !controller || controller->GetNumberOfProcesses() < 2)
  {
    return local;
  }
  if (vtkImageData::SafeDownCast(local))
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    if (controller->GetLocalProcessId() == 0)
    {
      image->ShallowCopy(local);
    }
    controller->Broadcast(image, 0);
    return image;
  }
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(local, pieces);
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    if (auto* surface = vtkPolyData::SafeDownCast(piece))
    {
      append->AddInputData(surface);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return local;
  }
  append->Update();
  return append->GetOutput();
}

parafluid::ParticleState ownParticlesInIdOrder(const parafluid::ParticleState& own)
{
  parafluid::ParticleState out = own;
  std::vector<std::uint32_t> byId(own.size());
  std::iota(byId.begin(), byId.end(), 0u);
  std::sort(byId.begin(), byId.end(), [&](std::uint32_t a, std::uint32_t b) { return own.id[a] < own.id[b]; });
  for (std::size_t k = 0; k < byId.size(); ++k)
  {
    out.originalIndex[byId[k]] = static_cast<std::uint32_t>(k);
  }
  return out;
}
} // namespace parafluid::vtk
