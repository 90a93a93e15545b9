// Fixture: a header outside every layer's folder.
#pragma once
