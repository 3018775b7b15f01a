// advance.cpp: stage 7 of the step (step.h): positions and orientations
// from the corrected velocities (integrate.cpp).
#include "step.h"

namespace karma::mdt {

void integratePartition(StepScratch &s, const Partition &part, MeReal h) {
  for (int i = 0; i < part.bodyCount; ++i) advanceBody(s.partBodies[(size_t)(part.bodyStart + i)], h);
}

}  // namespace karma::mdt
