#pragma once
// For VTK setters that write a field of a parameter struct (SPH Step's SPHParameters, the ocean's
// SeaSettings): assign, and mark the object modified only when the value changed.
#include "vtkObject.h"

namespace parafluid::vtk
{
template<class Field, class Value>
void assignIfChanged(vtkObject* owner, Field& field, Value value)
{
  if (field != static_cast<Field>(value))
  {
    field = static_cast<Field>(value);
    owner->Modified();
  }
}
} // namespace parafluid::vtk
