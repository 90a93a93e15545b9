// Fixture: f.h sits above the cycle of d.h and e.h without being on it.
#pragma once
#include "d.h"
