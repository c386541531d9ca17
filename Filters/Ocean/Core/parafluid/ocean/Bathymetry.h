#pragma once
// The sea floor under an ocean is a height field whose level is the sea level: depth() is the
// water depth. One class in Common serves the ocean, the carpet surface's terrain and later ones.
#include "parafluid/common/HeightField.h"

namespace parafluid::ocean
{
using Bathymetry = parafluid::HeightField;
} // namespace parafluid::ocean
