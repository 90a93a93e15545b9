// Fixture: an include with a folder prefix instead of the bare file name.
#pragma once
#include "high/b.h"
