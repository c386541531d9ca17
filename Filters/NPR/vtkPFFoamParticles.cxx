#include "vtkPFFoamParticles.h"

#include "GuardedRequest.h"
#include "LongWork.h"
#include "ParameterCheck.h"

#include "ParticleArrays.h"
#include "ProcessCommunicator.h"
#include "ProcessGather.h"

#include "parafluid/npr/FoamClassifier.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <stdexcept>

vtkStandardNewMacro(vtkPFFoamParticles);

vtkPFFoamParticles::vtkPFFoamParticles()
  : State(new parafluid::npr::FoamHysteresis)
  , StateBefore(new parafluid::npr::FoamHysteresis)
{
}

vtkPFFoamParticles::~vtkPFFoamParticles() = default;

void vtkPFFoamParticles::SetIdArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->IdArray)
  {
    this->IdArray = value;
    this->Modified();
  }
}

int vtkPFFoamParticles::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPFFoamParticles::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "Foam Particles",
    [&]() -> int
    {
      vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
      vtkPointSet* output = vtkPointSet::GetData(outputVector);
      if (!input || !output)
      {
        vtkErrorMacro("Foam Particles: the input is not a point set (particles)");
        return 0;
      }
      output->ShallowCopy(input);
      const vtkIdType n = input->GetNumberOfPoints();
      parafluid::vtk::ParameterCheck check;
      check.inRange("KernelRadius", this->KernelRadius, 1.0, 10.0, "particle spacings")
        .inRange("CrestThreshold", this->CrestThreshold, 0.01, 100.0)
        .require(parafluid::vtk::spacingPropertyProblem(this->ParticleSpacing, "ParticleSpacing").empty(),
                 parafluid::vtk::spacingPropertyProblem(this->ParticleSpacing, "ParticleSpacing"));
      if (!check.ok())
      {
        vtkErrorMacro("Foam Particles: " << check.problem());
        output->Initialize();
        return 0;
      }
      // Under MPI every process keeps its piece as output, but process 0 scores all particles
      // together (a particle's neighbours may be in another piece) and keeps the hysteresis of
      // every id, so the flags do not depend on the number of processes or on who holds whom.
      if (parafluid::vtk::processCount() > 1 && !this->Processes)
      {
        this->Processes = parafluid::vtk::makeProcessCommunicator();
      }
      parafluid::Communicator* processes = this->Processes.get();
      const bool scoresHere = !processes || processes->rank() == 0;
      double d = parafluid::vtk::particleSpacing(this->ParticleSpacing, input->GetFieldData());
      double total = static_cast<double>(n);
      if (processes)
      {
        d = processes->reduce(d, parafluid::Reduction::Max);
        total = processes->reduce(total, parafluid::Reduction::Sum);
      }
      if (total > 0.0 && !(d > 0.0))
      {
        vtkErrorMacro("Foam Particles: " << parafluid::vtk::missingSpacing("ParticleSpacing"));
        return 0;
      }
      parafluid::npr::FoamParameters p;
      p.kernelRadius = this->KernelRadius * (d > 0.0 ? d : 1.0);
      p.particleVolume = d > 0.0 ? d * d * d : 1.0;
      p.crestThreshold = this->CrestThreshold;
      p.sprayNeighbours = this->SprayNeighbours;
      const std::string problem = parafluid::npr::validate(p);
      if (!problem.empty())
      {
        vtkErrorMacro("Foam Particles: " << problem);
        return 0;
      }

      // Stable ids: the IdArray, else the point index (with a warning: foam then follows slots, not particles).
      std::vector<std::int64_t> ids(static_cast<std::size_t>(n));
      vtkDataArray* idArray = input->GetPointData()->GetArray(this->IdArray.c_str());
      if (n > 0 && !idArray)
      {
        vtkWarningMacro("Foam Particles: no point array '" << this->IdArray
                                                           << "' of particle ids; using point order, so foam follows "
                                                              "particles only if their order never changes");
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        ids[static_cast<std::size_t>(i)] = idArray ? static_cast<std::int64_t>(idArray->GetComponent(i, 0)) : i;
      }
      std::vector<float> positionStorage;
      const float* xyz = n > 0 ? parafluid::vtk::positionsAsFloat(input, positionStorage) : nullptr;
      std::vector<std::size_t> counts;
      std::vector<float> allPositions;
      if (processes)
      {
        std::vector<float> local(static_cast<std::size_t>(3 * n));
        std::copy_n(xyz, local.size(), local.data());
        allPositions = parafluid::vtk::gatherOnFirst(local, *processes, counts);
        ids = parafluid::vtk::gatherOnFirst(ids, *processes, counts);
        xyz = allPositions.data();
      }
      const std::size_t scored = scoresHere ? ids.size() : 0;

      // The status every process ends with: 0 scored, 1 an error (said on process 0), 2 aborted.
      int status = 0;
      parafluid::npr::FoamScores scores;
      std::vector<std::uint8_t> foam;
      if (scoresHere)
      {
        // Nominal cost on a 2-core machine: 1.2 us a particle (500 000 at the default settings).
        parafluid::vtk::LongWork work(
          this, "Foam Particles", { static_cast<double>(scored), 1.2e-6, "particles", "the input's particle count" });
        try
        {
          scores = parafluid::npr::scoreFoam(xyz, scored, p,
                                             [&work, scored](double fraction)
                                             { return work.advance(0.9 * fraction * static_cast<double>(scored)); });
          status = work.aborted() ? 2 : 0;
        }
        catch (const std::exception& e)
        {
          vtkErrorMacro("Foam Particles: " << parafluid::vtk::exceptionText(e));
          status = 1;
        }
      }
      if (processes)
      {
        status = static_cast<int>(processes->reduce(static_cast<double>(status), parafluid::Reduction::Max));
      }
      if (status != 0)
      {
        return status == 2 ? 1 : 0; // aborted: the scores are incomplete and the executive empties the output
      }

      // The hysteresis continues forward in time under unchanged settings; the same time again redoes
      // the last step; anything else starts again.
      const double time = input->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
                            ? input->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
                            : 0.0;
      const vtkMTimeType settings = this->GetMTime();
      const bool sameSettings = this->HasState && settings == this->StateSettings;
      if (sameSettings && time == this->LastTime)
      {
        *this->State = *this->StateBefore;
      }
      else if (sameSettings && time > this->LastTime)
      {
        *this->StateBefore = *this->State;
      }
      else
      {
        this->State->reset();
        this->StateBefore->reset();
      }
      if (scoresHere)
      {
        this->State->update(ids.data(), scores.candidate.data(), scored, this->PersistFrames, foam);
      }
      this->HasState = true;
      this->LastTime = time;
      this->StateSettings = settings;
      std::vector<float> score = std::move(scores.score);
      if (processes)
      {
        foam = parafluid::vtk::scatterFromFirst(foam, counts, 1, *processes);
        score = parafluid::vtk::scatterFromFirst(score, counts, 1, *processes);
      }

      vtkNew<vtkUnsignedCharArray> foamArray;
      foamArray->SetName("foam");
      foamArray->SetNumberOfTuples(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        foamArray->SetValue(i, foam[static_cast<std::size_t>(i)]);
      }
      output->GetPointData()->AddArray(foamArray);
      output->GetPointData()->AddArray(parafluid::vtk::floatArray("foam_score", 1, score));
      this->UpdateProgress(1.0);
      return 1;
    });
}

void vtkPFFoamParticles::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticleSpacing: " << this->ParticleSpacing << "\n";
  os << indent << "KernelRadius: " << this->KernelRadius << "\n";
  os << indent << "CrestThreshold: " << this->CrestThreshold << "\n";
  os << indent << "SprayNeighbours: " << this->SprayNeighbours << "\n";
  os << indent << "PersistFrames: " << this->PersistFrames << "\n";
  os << indent << "IdArray: " << this->IdArray << "\n";
}
