#include "vtkPFHDF5ParticleReader.h"

#include "GuardedRequest.h"
#include "OutputTimes.h"
#include "ParticleBlockRead.h"
#include "parafluid/h5part/Handle.h"
#include "parafluid/h5part/ParticleLayouts.h"
#include "vtkPFH5PartReader.h"

#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkPFHDF5ParticleReader);

struct vtkPFHDF5ParticleReader::Placed
{
  parafluid::h5::ParticleFileInfo info;
};

vtkPFHDF5ParticleReader::vtkPFHDF5ParticleReader()
  : File(std::make_unique<Placed>())
{
  this->SetNumberOfInputPorts(0);
  this->H5Part->AddObserver(vtkCommand::ErrorEvent, this, &vtkPFHDF5ParticleReader::PassOn);
  this->H5Part->AddObserver(vtkCommand::WarningEvent, this, &vtkPFHDF5ParticleReader::PassOn);
}

void vtkPFHDF5ParticleReader::PassOn(vtkObject*, unsigned long event, void* message)
{
  const char* text = static_cast<const char*>(message);
  if (event == vtkCommand::ErrorEvent)
  {
    this->H5PartFailed = true;
  }
  if (this->HasObserver(event))
  {
    this->InvokeEvent(event, message);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(text);
  }
  else
  {
    vtkOutputWindowDisplayWarningText(text);
  }
}

int vtkPFHDF5ParticleReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkPFHDF5ParticleReader::RequestDataObject(vtkInformation*, vtkInformationVector**,
                                               vtkInformationVector* outputVector)
{
  {
    parafluid::h5::QuietErrors quiet;
    std::string error;
    parafluid::h5::Handle file(parafluid::h5::openForReading(this->FileName, error), H5Fclose);
    // A .h5part file of no layout is read as H5Part too, so that its error says what H5Part lacks.
    const std::size_t dot = this->FileName.rfind('.');
    const std::string extension = dot == std::string::npos ? "" : this->FileName.substr(dot);
    const parafluid::h5::ParticleLayout layout =
      file.valid() ? parafluid::h5::detectLayout(file) : parafluid::h5::ParticleLayout::Unknown;
    this->ReadsH5Part =
      layout == parafluid::h5::ParticleLayout::H5Part ||
      (layout == parafluid::h5::ParticleLayout::Unknown && (extension == ".h5part" || extension == ".h5p"));
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  const char* wanted = this->ReadsH5Part ? "vtkPolyData" : "vtkMultiBlockDataSet";
  if (!output || !output->IsA(wanted))
  {
    vtkSmartPointer<vtkDataObject> made;
    if (this->ReadsH5Part)
    {
      made = vtkSmartPointer<vtkPolyData>::New();
    }
    else
    {
      made = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    }
    outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

void vtkPFHDF5ParticleReader::SyncH5PartSelection()
{
  for (int k = 0; k < this->PointArraySelection->GetNumberOfArrays(); ++k)
  {
    const char* name = this->PointArraySelection->GetArrayName(k);
    this->H5Part->SetPointArrayStatus(name, this->PointArraySelection->ArrayIsEnabled(name));
  }
  this->H5Part->SetSubset(this->Stride, this->UseSelectionBox, this->SelectionBox);
}

vtkPFHDF5ParticleReader::~vtkPFHDF5ParticleReader() = default;

int vtkPFHDF5ParticleReader::CanReadFile(const char* fileName)
{
  parafluid::h5::QuietErrors quiet;
  std::string error;
  parafluid::h5::Handle file(parafluid::h5::openForReading(fileName ? fileName : "", error), H5Fclose);
  return file.valid() && parafluid::h5::detectLayout(file) != parafluid::h5::ParticleLayout::Unknown ? 1 : 0;
}

int vtkPFHDF5ParticleReader::GetNumberOfPointArrays()
{
  return this->PointArraySelection->GetNumberOfArrays();
}

const char* vtkPFHDF5ParticleReader::GetPointArrayName(int index)
{
  return this->PointArraySelection->GetArrayName(index);
}

int vtkPFHDF5ParticleReader::GetPointArrayStatus(const char* name)
{
  return this->PointArraySelection->ArrayIsEnabled(name);
}

void vtkPFHDF5ParticleReader::SetPointArrayStatus(const char* name, int status)
{
  if (status)
  {
    this->PointArraySelection->EnableArray(name);
  }
  else
  {
    this->PointArraySelection->DisableArray(name);
  }
}

vtkMTimeType vtkPFHDF5ParticleReader::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->PointArraySelection->GetMTime());
}

void vtkPFHDF5ParticleReader::WarnOnce(const std::string& warning)
{
  if (this->Warned.insert(warning).second)
  {
    vtkWarningMacro("ParaFluid HDF5 Particles: " << warning);
  }
}

int vtkPFHDF5ParticleReader::RequestInformation(vtkInformation*, vtkInformationVector**,
                                                vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "ParaFluid HDF5 Particles",
    [&]() -> int
    {
      parafluid::h5::QuietErrors quiet; // what HDF5 would print is said in the errors below
      this->Warned.clear();
      if (this->ReadsH5Part)
      {
        this->DetectedLayout = "H5Part";
        this->H5PartFailed = false;
        this->H5Part->SetFileName(this->FileName.c_str());
        this->SyncH5PartSelection();
        this->H5Part->UpdateInformation();
        vtkDataArraySelection* found = this->H5Part->GetPointDataArraySelection();
        for (int k = 0; k < found->GetNumberOfArrays(); ++k)
        {
          if (!this->PointArraySelection->ArrayExists(found->GetArrayName(k)))
          {
            this->PointArraySelection->AddArray(found->GetArrayName(k));
          }
        }
        vtkInformation* from = this->H5Part->GetOutputInformation(0);
        vtkInformation* to = outputVector->GetInformationObject(0);
        to->CopyEntry(from, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
        to->CopyEntry(from, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
        to->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
        return this->H5PartFailed ? 0 : 1;
      }
      this->File->info = parafluid::h5::describeParticleFile(this->FileName, this->FileSeries);
      const parafluid::h5::ParticleFileInfo& info = this->File->info;
      this->DetectedLayout = info.error.empty() ? info.description : "";
      if (!info.error.empty())
      {
        vtkErrorMacro("ParaFluid HDF5 Particles: " << info.error);
        return 0;
      }
      for (const std::string& warning : info.warnings)
      {
        this->WarnOnce(warning);
      }
      // The arrays of the first frame's blocks, for the selection.
      const parafluid::h5::ParticleFrame first = parafluid::h5::describeFrame(info, 0);
      for (const auto& block : first.blocks)
      {
        for (const std::string& name : parafluid::vtk::blockArrayNames(block))
        {
          if (!this->PointArraySelection->ArrayExists(name.c_str()))
          {
            this->PointArraySelection->AddArray(name.c_str());
          }
        }
      }
      vtkInformation* outInfo = outputVector->GetInformationObject(0);
      outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), info.times.data(),
                   static_cast<int>(info.times.size()));
      const double range[2] = { info.times.front(), info.times.back() };
      outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
      outInfo->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
      return 1;
    });
}

int vtkPFHDF5ParticleReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "ParaFluid HDF5 Particles",
    [&]() -> int
    {
      parafluid::h5::QuietErrors quiet;
      vtkInformation* outInfo = outputVector->GetInformationObject(0);
      if (this->ReadsH5Part)
      {
        const parafluid::vtk::BlockReading piece = parafluid::vtk::blockReadingFor(outInfo, nullptr, nullptr);
        this->H5PartFailed = false;
        this->SyncH5PartSelection();
        if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
        {
          this->H5Part->UpdateTimeStep(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()), piece.piece,
                                       piece.pieces);
        }
        else
        {
          this->H5Part->UpdatePiece(piece.piece, piece.pieces, 0);
        }
        vtkPolyData* output = vtkPolyData::GetData(outInfo);
        output->ShallowCopy(this->H5Part->GetOutput());
        vtkInformation* read = this->H5Part->GetOutput()->GetInformation();
        if (read->Has(vtkDataObject::DATA_TIME_STEP()))
        {
          output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), read->Get(vtkDataObject::DATA_TIME_STEP()));
        }
        return this->H5PartFailed ? 0 : 1;
      }
      vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outInfo);
      const parafluid::h5::ParticleFileInfo& info = this->File->info;
      if (!info.error.empty() || info.times.empty())
      {
        vtkErrorMacro("ParaFluid HDF5 Particles: " << (info.error.empty() ? "no file read" : info.error));
        return 0;
      }
      // The time asked for: the nearest of the file's, the last past the end, NaN refused.
      std::size_t index = 0;
      if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
      {
        const double requested = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
        if (std::isnan(requested))
        {
          vtkErrorMacro(<< parafluid::vtk::notATimeError("ParaFluid HDF5 Particles"));
          return 0;
        }
        const double t = std::clamp(requested, info.times.front(), info.times.back());
        for (std::size_t k = 1; k < info.times.size(); ++k)
        {
          index = std::fabs(info.times[k] - t) < std::fabs(info.times[index] - t) ? k : index;
        }
      }
      const parafluid::h5::ParticleFrame frame = parafluid::h5::describeFrame(info, index);
      if (!frame.error.empty())
      {
        vtkErrorMacro("ParaFluid HDF5 Particles: '" << this->FileName << "': " << frame.error);
        return 0;
      }
      for (const std::string& warning : frame.warnings)
      {
        this->WarnOnce(warning);
      }
      parafluid::vtk::BlockReading how = parafluid::vtk::blockReadingFor(outInfo, this->PointArraySelection, this);
      how.stride = this->Stride;
      how.useBox = this->UseSelectionBox;
      std::copy(this->SelectionBox, this->SelectionBox + 6, how.box);
      for (int a = 0; a < 3 && how.useBox; ++a)
      {
        if (!std::isfinite(how.box[2 * a]) || !std::isfinite(how.box[2 * a + 1]) || how.box[2 * a] > how.box[2 * a + 1])
        {
          vtkErrorMacro("ParaFluid HDF5 Particles: SelectionBox must be finite with min <= max on every axis; axis "
                        << "xyz"[a] << " is [" << how.box[2 * a] << ", " << how.box[2 * a + 1] << "]");
          return 0;
        }
      }
      output->SetNumberOfBlocks(static_cast<unsigned int>(frame.blocks.size()));
      for (std::size_t b = 0; b < frame.blocks.size(); ++b)
      {
        vtkNew<vtkPolyData> particles;
        std::vector<std::string> warnings;
        std::string error;
        if (!parafluid::vtk::readParticleBlock(frame.blocks[b], how, particles, warnings, error))
        {
          vtkErrorMacro("ParaFluid HDF5 Particles: " << error);
          output->Initialize();
          return 0;
        }
        for (const std::string& warning : warnings)
        {
          this->WarnOnce(warning);
        }
        for (const auto& field : frame.fields)
        {
          vtkNew<vtkDoubleArray> values;
          values->SetName(field.name.c_str());
          for (double v : field.values)
          {
            values->InsertNextValue(v);
          }
          particles->GetFieldData()->AddArray(values);
        }
        output->SetBlock(static_cast<unsigned int>(b), particles);
        output->GetMetaData(static_cast<unsigned int>(b))
          ->Set(vtkCompositeDataSet::NAME(), frame.blocks[b].name.c_str());
        this->UpdateProgress(static_cast<double>(b + 1) / static_cast<double>(frame.blocks.size()));
      }
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), frame.time);
      return 1;
    });
}

void vtkPFHDF5ParticleReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "DetectedLayout: " << this->DetectedLayout << "\n";
  os << indent << "Stride: " << this->Stride << "\n";
  os << indent << "UseSelectionBox: " << this->UseSelectionBox << "\n";
  os << indent << "SelectionBox: " << this->SelectionBox[0] << " " << this->SelectionBox[1] << " "
     << this->SelectionBox[2] << " " << this->SelectionBox[3] << " " << this->SelectionBox[4] << " "
     << this->SelectionBox[5] << "\n";
  os << indent << "FileSeries: " << this->FileSeries << "\n";
}
