// bsjoint.cpp: the ball-and-socket joint -- three rows that make the two
// attachment points coincide:  p0 - p1 = 0.
#include "MdtBSJoint.h"
#include "bcl_type.h"

using namespace karma::mdt;

struct MdtBSJoint : MdtConstraint {};

namespace {

void reset(MdtConstraint *) {}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) { addPointRows(sink, ctx, anchorsOf(c)); }

}  // namespace

namespace karma::mdt {
extern const ConstraintType kBSJointType = {
    MdtConstraintTypeBSJoint, "BSJoint", sizeof(MdtBSJoint), 3, nullptr, reset, addRows, nullptr, nullptr, nullptr};
}

MDT_DEFINE_CONSTRAINT_TYPE(BSJoint, kBSJointType)
