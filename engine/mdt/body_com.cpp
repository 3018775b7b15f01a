// body_com.cpp: the centre of mass relative to the body frame.
//
// A body's position and TM are those of its body frame (the frame collision
// models and graphics follow). Its centre of mass sits at c in that frame,
// with its own axes (the COM frame, comTM relative to the body frame). The
// inertia tensor is given about the centre of mass in the COM frame's axes;
// the dynamics uses it in body axes, I_b = Rc^T I_c Rc (Rc: rows are the COM
// axes in body coordinates). Linear velocity is the velocity of the centre
// of mass; forces added with MdtBodyAddForce act through it, and lever arms
// (AtPosition, joints, contacts) are measured from it.
#include "MeMessage.h"
#include "mdt_internal.h"

namespace karma::mdt {

void bodyCom(const MdtBody *b, MeVector3 out) {
  MeVector3 c;
  MeMatrix4TMGetPosition(c, b->comTM);
  MeMatrix4TMTransform(out, b->tm, c);
}

void updateInertia(MdtBody *b) {
  MeMatrix3 Rc, RcT, tmp;
  MeMatrix4TMGetRotation(Rc, b->comTM);
  MeMatrix3Transpose(RcT, Rc);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      MeReal s = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s += RcT[i][k] * b->inertiaCom[k][l] * Rc[l][j];
      tmp[i][j] = s;
    }
  MeMatrix3Copy(b->inertia, tmp);
  MeMatrix3Inverse(b->invInertia, tmp);  // positive definite, checked on the way in
  classifyInertia(b);
}

}  // namespace karma::mdt

using namespace karma::mdt;

extern "C" {

void MEAPI MdtBodySetCenterOfMassRelativeTransform(const MdtBodyID body, MECONSTMATRIX MeMatrix4 tm) {
  static const char *fn = "MdtBodySetCenterOfMassRelativeTransform";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(tm != nullptr, fn, "NULL argument");
  bool finite = true;
  for (int i = 0; i < 4; ++i) finite = finite && MeVector3AllFinite(tm[i]);
  ME_REQUIRE_ARG(finite, fn, "transform is not finite; ignored");
  ME_REQUIRE_ARG(MeMatrix4IsTM(tm, (MeReal)1e-3), fn,
                 "not a rigid transform (rotation rows must be orthonormal); ignored");
  MeMatrix4Copy(body->comTM, tm);
  updateInertia(body);
}

void MEAPI MdtBodyGetCenterOfMassRelativeTransform(const MdtBodyID body, MeMatrix4 tm) {
  if (!liveBody(body, "MdtBodyGetCenterOfMassRelativeTransform")) return;
  ME_REQUIRE_ARG(tm != nullptr, "MdtBodyGetCenterOfMassRelativeTransform", "NULL argument");
  MeMatrix4Copy(tm, body->comTM);
}

void MEAPI MdtBodySetCenterOfMassRelativePosition(const MdtBodyID body, const MeVector3 pos) {
  static const char *fn = "MdtBodySetCenterOfMassRelativePosition";
  if (!liveBody(body, fn)) return;
  ME_REQUIRE_ARG(pos != nullptr, fn, "NULL argument");
  ME_REQUIRE_ARG(MeVector3AllFinite(pos), fn, "position is not finite; ignored");
  MeMatrix4TMSetPositionVector(body->comTM, pos);
}

void MEAPI MdtBodyGetCenterOfMassRelativePosition(const MdtBodyID body, MeVector3 pos) {
  if (!liveBody(body, "MdtBodyGetCenterOfMassRelativePosition")) return;
  ME_REQUIRE_ARG(pos != nullptr, "MdtBodyGetCenterOfMassRelativePosition", "NULL argument");
  MeMatrix4TMGetPosition(pos, body->comTM);
}

void MEAPI MdtBodyGetCenterOfMassPosition(const MdtBodyID body, MeVector3 pos) {
  if (!liveBody(body, "MdtBodyGetCenterOfMassPosition")) return;
  ME_REQUIRE_ARG(pos != nullptr, "MdtBodyGetCenterOfMassPosition", "NULL argument");
  bodyCom(body, pos);
}

}  // extern "C"
