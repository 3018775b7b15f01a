// space_aliases.cpp: the older McdSpace names the guide's prose still uses
// (McdSpace.h lists each with the function it is): same arguments, same
// result, the same function underneath.
#include "McdSpace.h"

extern "C" {

void MEAPI McdSpaceUpdate(McdSpaceID space) { McdSpaceUpdateAll(space); }

void MEAPI McdSpaceUpdateAllModels(McdSpaceID space) { McdSpaceUpdateModels(space); }

MeBool MEAPI McdSpaceIsFrozen(McdModelID model) { return McdSpaceModelIsFrozen(model); }

MeBool MEAPI McdUnfreezeInSpace(McdModelID model) { return McdSpaceUnfreezeModel(model); }

MeBool MEAPI McdDisablePair(McdModelID model1, McdModelID model2) { return McdSpaceDisablePair(model1, model2); }

}  // extern "C"
