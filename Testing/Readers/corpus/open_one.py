"""Opens one corpus file with the ParaFluid H5Part reader (or ParaFluid HDF5 Particles) and says what it gave.

open_file(path) returns a dict: the error and warning texts, the first step's particle count, the
first values of each point array, the field data, the number of time steps and the last step's
particle count. The corpus driver calls it in a process of its own per file.
"""
import math

from paraview.simple import *
from paraview import servermanager
import pftest


def number(v):
    v = float(v)
    return v if math.isfinite(v) else str(v)


def values(array, limit=8):
    n = min(array.GetNumberOfValues(), limit)
    if array.IsA("vtkStringArray"):
        return [array.GetValue(k) for k in range(n)]
    return [number(array.GetValue(k)) for k in range(n)]


def open_file(path, reader_type):
    reader = reader_type()
    messages = pftest.Messages(reader.GetClientSideObject())
    reader.FileName = path  # after the observers: RequestInformation's warnings count too
    reader.UpdatePipelineInformation()
    reader.UpdatePipeline()
    data = servermanager.Fetch(reader)
    steps = list(reader.TimestepValues) if reader.TimestepValues else []
    result = {"steps": len(steps)}
    if data is not None and data.IsA("vtkMultiBlockDataSet"):
        # ParaFluid HDF5 Particles: every block's particles count, the first block's arrays are shown.
        blocks = [data.GetBlock(b) for b in range(data.GetNumberOfBlocks()) if data.GetBlock(b) is not None]
        total = sum(b.GetNumberOfPoints() for b in blocks)
        data = blocks[0] if blocks else None
        if data is not None:
            result["blocks"] = len(blocks)
    else:
        total = data.GetNumberOfPoints() if data is not None else 0
    if data is not None and not messages.errors:
        result["points"] = total
        pd, fd = data.GetPointData(), data.GetFieldData()
        result["arrays"] = {pd.GetArray(i).GetName(): values(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
        result["field"], result["strings"] = {}, {}
        for i in range(fd.GetNumberOfArrays()):
            a = fd.GetAbstractArray(i)
            result["strings" if a.IsA("vtkStringArray") else "field"][a.GetName()] = values(a)
        if len(steps) > 1:
            reader.UpdatePipeline(steps[-1])
            last = servermanager.Fetch(reader)
            result["last_points"] = last.GetNumberOfPoints() if last is not None else None
    result["error"] = " | ".join(messages.errors)
    result["warning"] = " | ".join(messages.warnings)
    return result
