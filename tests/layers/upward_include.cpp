// Compiled against hobsharp_math alone, by the test core_layers_enforced_by_links: a math file
// that reaches up to the grinding layer must not compile, because envelope.h is not on math's
// include path.
#include "envelope.h"
