#include "vtkPFParticleAlgorithm.h"

#include "ParticleArrays.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <exception>
#include <new>

vtkPFParticleAlgorithm::vtkPFParticleAlgorithm(const char* label)
  : Label(label)
{
}

vtkPFParticleAlgorithm::~vtkPFParticleAlgorithm() = default;

void vtkPFParticleAlgorithm::ReportError(const std::string& message)
{
  vtkErrorMacro(<< this->Label << ": " << message);
}

double vtkPFParticleAlgorithm::ParticleSpacingOr(double property, vtkPointSet* input, const char* propertyName)
{
  const double d = parafluid::vtk::particleSpacing(property, input->GetFieldData());
  if (!(d > 0.0))
  {
    this->ReportError(parafluid::vtk::missingSpacing(propertyName));
    return 0.0;
  }
  return d;
}

int vtkPFParticleAlgorithm::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                        vtkInformationVector* outputVector)
{
  vtkPointSet* local = vtkPointSet::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (!local)
  {
    this->ReportError("the input is not a point set (particles)");
    return 0;
  }
  // A particle needs its neighbours from every piece: under MPI the pieces are gathered on process
  // 0, which does the work (ghost exchange would let each process keep its own). Every process
  // takes part in every gather before any of them returns.
  bool holdsAll = true;
  vtkSmartPointer<vtkDataObject> gathered = parafluid::vtk::gatherToFirstProcess(local, holdsAll);
  vtkSmartPointer<vtkDataObject> gatheredExtra;
  vtkPointSet* localExtra =
    this->GatheredInputPort >= 0 && inputVector[this->GatheredInputPort]->GetNumberOfInformationObjects() > 0
      ? vtkPointSet::GetData(inputVector[this->GatheredInputPort])
      : nullptr;
  if (localExtra)
  {
    bool extraHere = true;
    gatheredExtra = parafluid::vtk::gatherToFirstProcess(localExtra, extraHere);
  }
  int result = 1;
  if (!holdsAll)
  {
    output->Initialize();
  }
  else
  {
    Particles particles;
    particles.Gathered = vtkPointSet::SafeDownCast(gathered);
    particles.Local = local;
    particles.Extra = vtkPointSet::SafeDownCast(gatheredExtra);
    // Cores throw std::invalid_argument for what they cannot do and std::bad_alloc when memory
    // runs out: both become an error message, never an abort of ParaView.
    try
    {
      result = this->RequestParticles(particles, inputVector, outInfo, output);
    }
    catch (const std::bad_alloc&)
    {
      this->ReportError("not enough memory for this many particles at these settings");
      result = 0;
    }
    catch (const std::exception& e)
    {
      this->ReportError(e.what());
      result = 0;
    }
    if (!result)
    {
      output->Initialize();
    }
  }
  // Process 0's verdict is every process's: an error there must not leave the others running on
  // into a collective call that process 0 never makes.
  return parafluid::vtk::agreeOnAllProcesses(result != 0) ? 1 : 0;
}
