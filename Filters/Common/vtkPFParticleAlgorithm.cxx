#include "vtkPFParticleAlgorithm.h"

#include "GuardedRequest.h"
#include "ParticleArrays.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
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
  const std::string problem = parafluid::vtk::spacingPropertyProblem(property, propertyName);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return 0.0;
  }
  const double d = parafluid::vtk::particleSpacing(property, input->GetFieldData());
  if (!(d > 0.0))
  {
    this->ReportError(parafluid::vtk::missingSpacing(propertyName));
    return 0.0;
  }
  return d;
}

vtkSmartPointer<vtkPointSet> vtkPFParticleAlgorithm::ApplyNonFinitePolicy(vtkPointSet* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkDataArray*> arrays;
  for (const std::string& name : this->FiniteArrays)
  {
    if (vtkDataArray* array = input->GetPointData()->GetArray(name.c_str()))
    {
      arrays.push_back(array);
    }
  }
  // Which particles are bad, and what of them.
  std::vector<char> keep(static_cast<std::size_t>(n), 1);
  vtkIdType bad = 0, firstBad = -1;
  std::string firstWhat;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    std::string what = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) ? "" : "position";
    for (std::size_t k = 0; k < arrays.size() && what.empty(); ++k)
    {
      for (int c = 0; c < arrays[k]->GetNumberOfComponents(); ++c)
      {
        if (!std::isfinite(arrays[k]->GetComponent(i, c)))
        {
          what = this->FiniteArrays[k];
          break;
        }
      }
    }
    if (!what.empty())
    {
      keep[static_cast<std::size_t>(i)] = 0;
      if (bad++ == 0)
      {
        firstBad = i;
        firstWhat = what;
      }
    }
  }
  if (bad == 0)
  {
    return input;
  }
  const std::string example = "particle " + std::to_string(firstBad) + " has a NaN or infinite " + firstWhat;
  if (this->NonFinitePolicy == NonFinite::Refuse)
  {
    this->ReportError(example + " (" + std::to_string(bad) +
                      " particles have such values); this filter needs finite input: fix or remove them upstream");
    return nullptr;
  }
  vtkWarningMacro(<< this->Label << ": " << bad << " of " << n
                  << " particles were left out for NaN or infinite values (" << example << ")");
  auto finite = vtkSmartPointer<vtkPolyData>::New();
  finite->GetFieldData()->ShallowCopy(input->GetFieldData());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n - bad);
  finite->GetPointData()->CopyAllocate(input->GetPointData(), n - bad);
  vtkIdType out = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (keep[static_cast<std::size_t>(i)])
    {
      points->SetPoint(out, input->GetPoint(i));
      finite->GetPointData()->CopyData(input->GetPointData(), i, out);
      ++out;
    }
  }
  finite->SetPoints(points);
  return finite;
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
  const bool pieces = parafluid::vtk::processCount() > 1 && this->WorksOnPieces();
  vtkSmartPointer<vtkDataObject> gathered = pieces ? local : parafluid::vtk::gatherToFirstProcess(local, holdsAll);
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
    vtkSmartPointer<vtkPointSet> finite = this->ApplyNonFinitePolicy(vtkPointSet::SafeDownCast(gathered));
    if (pieces && !parafluid::vtk::agreeOnAllProcesses(finite != nullptr))
    {
      // Every process works on its piece collectively: none starts when one refused its input.
      output->Initialize();
      return 0;
    }
    Particles particles;
    particles.Gathered = finite;
    particles.Local = local;
    particles.Extra = vtkPointSet::SafeDownCast(gatheredExtra);
    // Cores throw std::invalid_argument for what they cannot do and std::bad_alloc when memory
    // runs out: both become an error message, never an abort of ParaView.
    try
    {
      result = finite ? this->RequestParticles(particles, inputVector, outInfo, output) : 0;
    }
    catch (const std::bad_alloc&)
    {
      this->ReportError("not enough memory for this many particles at these settings");
      result = 0;
    }
    catch (const std::exception& e)
    {
      this->ReportError(parafluid::vtk::exceptionText(e));
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
