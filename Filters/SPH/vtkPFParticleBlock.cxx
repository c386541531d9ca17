#include "vtkPFParticleBlock.h"

#include "GuardedRequest.h"
#include "ParameterCheck.h"
#include "parafluid/common/MemoryBudget.h"

#include "ParticleArrays.h"

#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHParameters.h"

#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTypeInt64Array.h"
#include <cmath>

#include <exception>

vtkStandardNewMacro(vtkPFParticleBlock);

vtkPFParticleBlock::vtkPFParticleBlock()
{
  this->SetNumberOfInputPorts(0);
}

int vtkPFParticleBlock::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "Particle Block",
    [&]() -> int
    {
      vtkPolyData* output = vtkPolyData::GetData(outputVector);
      double count = 0.0;
      if (!this->CheckProperties(count))
      {
        return 0;
      }
      this->UpdateProgress(0.0);
      const double h = 2.0 * this->Spacing; // about 33 neighbours inside the kernel radius
      parafluid::ParticleLattice lattice;
      float mass = 0.0f;
      try
      {
        lattice = parafluid::fillBoxWithLattice({ this->BlockBounds[0], this->BlockBounds[1], this->BlockBounds[2],
                                                  this->BlockBounds[3], this->BlockBounds[4], this->BlockBounds[5] },
                                                this->Spacing);
        mass = parafluid::sph::latticeParticleMass(static_cast<float>(this->Spacing), static_cast<float>(h),
                                                   static_cast<float>(this->RestDensity));
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro("Particle Block: " << parafluid::vtk::exceptionText(e));
        return 0;
      }
      this->WriteBlock(lattice, mass, h, output);
      return 1;
    });
}

bool vtkPFParticleBlock::CheckProperties(double& count)
{
  parafluid::vtk::ParameterCheck check;
  check.inRange("Spacing", this->Spacing, 1e-6, 1e3, "m")
    .box("BlockBounds", this->BlockBounds, false)
    .box("DomainBounds", this->DomainBounds, true)
    .inRange("RestDensity", this->RestDensity, 1e-6, 1e6, "kg/m^3");
  // What the block will take: about 60 bytes a particle (position, velocity, density, pressure,
  // mass, id, vertex), checked before the lattice is made.
  count = 1.0;
  for (int a = 0; a < 3 && check.ok(); ++a)
  {
    count *= std::floor((this->BlockBounds[2 * a + 1] - this->BlockBounds[2 * a]) / this->Spacing + 1e-9) + 1.0;
  }
  const std::string memory =
    check.ok() ? parafluid::checkMemoryBudget(60.0 * count, "a block of " + std::to_string(count) + " particles")
               : std::string();
  check.require(memory.empty(), memory + "; raise Spacing or shrink BlockBounds");
  if (!check.ok())
  {
    vtkErrorMacro("Particle Block: " << check.problem());
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (this->BlockBounds[2 * a] < this->DomainBounds[2 * a] ||
        this->BlockBounds[2 * a + 1] > this->DomainBounds[2 * a + 1])
    {
      vtkWarningMacro("Particle Block: BlockBounds reach outside DomainBounds along "
                      << "xyz"[a] << ": SPH Step reflects those particles inside, onto others");
      break;
    }
  }
  if (count > 1e7)
  {
    vtkWarningMacro("Particle Block: " << count / 1e6
                                       << " million particles: filters downstream (SPH Step) will be slow");
  }
  return true;
}

void vtkPFParticleBlock::WriteBlock(const parafluid::ParticleLattice& lattice, float mass, double h,
                                    vtkPolyData* output)
{
  const auto n = static_cast<vtkIdType>(lattice.x.size());
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  float* p = coordinates->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    p[3 * i + 0] = lattice.x[i];
    p[3 * i + 1] = lattice.y[i];
    p[3 * i + 2] = lattice.z[i];
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  parafluid::vtk::setOneVertexPerPoint(output, n);

  this->UpdateProgress(0.5);
  auto addScalar = [&](const char* name, float value)
  {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfValues(n);
    a->FillValue(value);
    output->GetPointData()->AddArray(a);
  };
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName(parafluid::contract::Velocity);
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(n);
  velocity->FillValue(0.0f);
  output->GetPointData()->SetVectors(velocity);
  addScalar(parafluid::contract::Density, static_cast<float>(this->RestDensity));
  addScalar(parafluid::contract::Pressure, 0.0f);
  addScalar(parafluid::contract::Mass, mass);
  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(parafluid::contract::Id);
  ids->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ids->SetValue(i, i);
  }
  output->GetPointData()->AddArray(ids);

  vtkFieldData* fd = output->GetFieldData();
  parafluid::vtk::setFieldValue(fd, parafluid::contract::ParticleSpacing, &this->Spacing, 1);
  parafluid::vtk::setFieldValue(fd, parafluid::contract::SmoothingLength, &h, 1);
  parafluid::vtk::setFieldValue(fd, parafluid::contract::RestDensity, &this->RestDensity, 1);
  parafluid::vtk::setFieldValue(fd, parafluid::contract::DomainBounds, this->DomainBounds, 6);
}

void vtkPFParticleBlock::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "RestDensity: " << this->RestDensity << "\n";
}
