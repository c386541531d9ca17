#pragma once
// A filter's enumeration property: a value that is none of its choices is refused with an error
// that names the property and lists the choices, and the current setting is kept.
#include "vtkObject.h"

#include <initializer_list>
#include <sstream>

namespace parafluid::vtk
{
/// True when 0 <= value < the number of choices (labelled as in the GUI); otherwise reports
/// "<property> = <value> is not one of 0 (<first>), 1 (...); kept <kept>" as `self`'s error.
inline bool isChoice(vtkObject* self, const char* property, int value, std::initializer_list<const char*> choices,
                     int kept)
{
  if (value >= 0 && value < static_cast<int>(choices.size()))
  {
    return true;
  }
  std::ostringstream text;
  text << property << " = " << value << " is not one of";
  int k = 0;
  for (const char* label : choices)
  {
    text << (k == 0 ? " " : ", ") << k << " (" << label << ")";
    ++k;
  }
  text << "; kept " << kept;
  vtkErrorWithObjectMacro(self, << text.str());
  return false;
}
} // namespace parafluid::vtk
