#include "SPHScenes.h"
