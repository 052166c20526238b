#pragma once
// Clears the upper halves of the AVX registers (vzeroupper) when the CPU has AVX. Code outside the
// engine (Qt, glibc string routines) can leave them dirty; then every SSE instruction of the engine
// and of libm (atan2, log, exp) pays a transition penalty. Measured in millexpert-cli: the margined
// ZOA lobes ran 5-8 times slower than in a plain binary until this was called at the entry of the
// hot paths (docs/performance.md). A no-op on CPUs without AVX.
namespace mx {

void clearUpperVectorState();

}  // namespace mx
