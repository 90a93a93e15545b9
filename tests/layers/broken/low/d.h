// Fixture: d.h and e.h include each other.
#pragma once
#include "e.h"
