// Fixture: a header of the high layer.
#pragma once
