// constraint_aliases.cpp: the guide's deprecated names of the constraint
// axis functions (MdtConstraint.h), each the same function as its new name.
#include "MdtConstraint.h"

extern "C" {

void MEAPI MdtConstraintSetBothAxis(const MdtConstraintID c, const MeReal px, const MeReal py, const MeReal pz,
                                    const MeReal ox, const MeReal oy, const MeReal oz) {
  MdtConstraintSetAxes(c, px, py, pz, ox, oy, oz);
}

void MEAPI MdtConstraintGetBothAxes(const MdtConstraintID c, MeVector3 primary, MeVector3 ortho) {
  MdtConstraintGetAxes(c, primary, ortho);
}

void MEAPI MdtConstraintBodyGetBothAxes(const MdtConstraintID c, const unsigned int bodyindex, MeVector3 primary,
                                        MeVector3 ortho) {
  MdtConstraintBodyGetAxes(c, bodyindex, primary, ortho);
}

}  // extern "C"
