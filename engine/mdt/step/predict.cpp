// predict.cpp: stage 2 of the step (step.h): each body's velocity after
// the forces alone, v* = v + h M^-1 f (integrate.cpp), before constraints.
#include "step.h"

namespace karma::mdt {

void predictPartition(MdtWorldID world, StepScratch &s, const Partition &part, MeReal h) {
  accumulateGeometricStiffness(world, s, part);
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    b->index = i;  // the body's index within its partition, for the rows
    predictVelocities(b, world->params.gravity, h);
  }
}

}  // namespace karma::mdt
