// Fixture: a low-layer header that includes a header of the higher layer.
#pragma once
#include "b.h"
