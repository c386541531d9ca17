#include "FluidParticleGather.h"

#include "parafluid/common/Communicator.h"

#include "vtkAppendPolyData.h"
#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cstring>
#include <stdexcept>
#include <vector>

namespace parafluid
{
vtkSmartPointer<vtkPolyData> gatherParticlesOnFirst(vtkPolyData* local, Communicator& processes)
{
  std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(processes.size()));
  if (local && local->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkCharArray> buffer;
    if (!vtkCommunicator::MarshalDataObject(local, buffer))
    {
      throw std::runtime_error("the particles could not be packed to send to process 0");
    }
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(buffer->GetPointer(0));
    sends[0].assign(bytes, bytes + buffer->GetNumberOfValues());
  }
  const auto received = processes.exchange(sends);
  auto all = vtkSmartPointer<vtkPolyData>::New();
  if (processes.rank() != 0)
  {
    return all;
  }
  vtkNew<vtkAppendPolyData> append;
  vtkFieldData* fieldData = nullptr;
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  for (const auto& message : received)
  {
    if (message.empty())
    {
      continue;
    }
    vtkNew<vtkCharArray> buffer;
    buffer->SetNumberOfValues(static_cast<vtkIdType>(message.size()));
    std::memcpy(buffer->GetPointer(0), message.data(), message.size());
    pieces.push_back(vtkCommunicator::UnMarshalDataObject(buffer));
    auto* piece = vtkPolyData::SafeDownCast(pieces.back());
    if (piece && piece->GetNumberOfPoints() > 0)
    {
      append->AddInputData(piece);
      fieldData = fieldData ? fieldData : piece->GetFieldData();
    }
  }
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    all->ShallowCopy(append->GetOutput());
    all->GetFieldData()->ShallowCopy(fieldData);
  }
  return all;
}
} // namespace parafluid
