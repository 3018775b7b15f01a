// ragdoll_scene.cpp: SCENES.md's "ragdoll": ten bodies (boxes and
// capsules, 67 kg) joined by nine ball-and-socket joints, built standing,
// tilted 0.4 rad about (1, 0, 0.5) and dropped from 2 m; its parts collide
// only with the ground. Joint error is the gap between a joint's anchor as
// carried by each of its two bodies.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "anchor_scene.h"

namespace karma::scenes {

namespace {

enum Shape { kBox, kCapsuleX, kCapsuleY };

struct Part {
  Shape shape;
  double a, b, c;  // box: dimensions; capsule: radius, length
  double mass;
  double x, y, z;  // centre, standing
};

struct Joint {
  int parent, child;
  double x, y, z;  // anchor, standing
};

const Part kParts[10] = {
    {kBox, 0.36, 0.55, 0.20, 30, 0, 1.225, 0},        // 0 torso
    {kBox, 0.20, 0.24, 0.20, 5, 0, 1.62, 0},          // 1 head
    {kCapsuleX, 0.05, 0.30, 0, 2.5, 0.33, 1.42, 0},   // 2 upper arm L
    {kCapsuleX, 0.05, 0.30, 0, 2.5, -0.33, 1.42, 0},  // 3 upper arm R
    {kCapsuleX, 0.04, 0.28, 0, 1.5, 0.62, 1.42, 0},   // 4 forearm L
    {kCapsuleX, 0.04, 0.28, 0, 1.5, -0.62, 1.42, 0},  // 5 forearm R
    {kCapsuleY, 0.07, 0.45, 0, 8, 0.1, 0.725, 0},     // 6 thigh L
    {kCapsuleY, 0.07, 0.45, 0, 8, -0.1, 0.725, 0},    // 7 thigh R
    {kCapsuleY, 0.06, 0.44, 0, 4, 0.1, 0.28, 0},      // 8 calf L
    {kCapsuleY, 0.06, 0.44, 0, 4, -0.1, 0.28, 0},     // 9 calf R
};

const Joint kJoints[9] = {
    {0, 1, 0, 1.50, 0},     {0, 2, 0.18, 1.42, 0}, {0, 3, -0.18, 1.42, 0},
    {2, 4, 0.48, 1.42, 0},  {3, 5, -0.48, 1.42, 0}, {0, 6, 0.1, 0.95, 0},
    {0, 7, -0.1, 0.95, 0},  {6, 8, 0.1, 0.50, 0},  {7, 9, -0.1, 0.50, 0},
};

// Rotation by `angle` about the unit axis k (column-vector matrix).
void AxisAngle(double M[3][3], const double k[3], double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  M[0][0] = t * k[0] * k[0] + c;        M[0][1] = t * k[0] * k[1] - s * k[2];
  M[0][2] = t * k[0] * k[2] + s * k[1]; M[1][0] = t * k[0] * k[1] + s * k[2];
  M[1][1] = t * k[1] * k[1] + c;        M[1][2] = t * k[1] * k[2] - s * k[0];
  M[2][0] = t * k[0] * k[2] - s * k[1]; M[2][1] = t * k[1] * k[2] + s * k[0];
  M[2][2] = t * k[2] * k[2] + c;
}

void Apply(const double M[3][3], const double in[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = M[i][0] * in[0] + M[i][1] * in[1] + M[i][2] * in[2];
}

class RagdollScene final : public AnchorScene {
 public:
  RagdollScene() : AnchorScene("ragdoll", 600, 16, 16, 64, 128) {
    ground(material((MeReal)0.4));
    const MstMaterialID m = material((MeReal)0.4);
    const double len = std::sqrt(1.25), axis[3] = {1 / len, 0, 0.5 / len};
    double M[3][3];
    AxisAngle(M, axis, 0.4);
    // Body axes (rows) standing: capsules lie along their local z.
    const double alongX[3][3] = {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}};
    const double alongY[3][3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    const double upright[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 10; ++i) {
      const Part &p = kParts[i];
      McdGeometryID g =
          p.shape == kBox ? McdBoxCreate(framework(), (MeReal)p.a, (MeReal)p.b, (MeReal)p.c)
                          : McdSphylCreate(framework(), (MeReal)p.a, (MeReal)p.b);
      const double(*rows)[3] = p.shape == kBox ? upright : p.shape == kCapsuleX ? alongX : alongY;
      MeMatrix3 R;
      for (int r = 0; r < 3; ++r) {
        double turned[3];
        Apply(M, rows[r], turned);
        for (int k = 0; k < 3; ++k) R[r][k] = (MeReal)turned[k];
      }
      const double standing[3] = {p.x, p.y, p.z};
      double at[3];
      Apply(M, standing, at);
      const MeVector3 pos = {(MeReal)at[0], (MeReal)at[1], (MeReal)at[2]};
      part_[i] = body(g, (MeReal)p.mass, pos, m, &R);
    }
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < i; ++j) disablePair(part_[i], part_[j]);
    // Lift so that the lowest point is at y = 2.
    double lowest = 1e9;
    for (McdModelID model : part_) {
      McdModelUpdate(model);
      MeVector3 mn, mx;
      McdModelGetAABB(model, mn, mx);
      lowest = std::min(lowest, (double)mn[1]);
    }
    const MeReal lift = (MeReal)(2.0 - lowest);
    for (McdModelID model : part_) {
      MdtBodyID b = McdModelGetBody(model);
      MeVector3 x;
      MdtBodyGetPosition(b, x);
      MdtBodySetPosition(b, x[0], x[1] + lift, x[2]);
    }
    for (int j = 0; j < 9; ++j) {
      const Joint &d = kJoints[j];
      const double standing[3] = {d.x, d.y, d.z};
      double at[3];
      Apply(M, standing, at);
      joint_[j] = MdtBSJointCreate(world());
      MdtBSJointSetBodies(joint_[j], McdModelGetBody(part_[d.parent]),
                          McdModelGetBody(part_[d.child]));
      MdtBSJointSetPosition(joint_[j], (MeReal)at[0], (MeReal)at[1] + lift, (MeReal)at[2]);
      MdtBSJointEnable(joint_[j]);
    }
  }

 private:
  double jointError() const {
    double worst = 0;
    for (MdtBSJointID j : joint_) {
      MeVector3 p0, p1;
      MdtConstraintID c = MdtBSJointQuaConstraint(j);
      MdtConstraintBodyGetPosition(c, 0, p0);
      MdtConstraintBodyGetPosition(c, 1, p1);
      worst = std::max(worst, (double)MeVector3Distance(p0, p1));
    }
    return worst;
  }
  void afterStep() override {
    figures_.jointErrorMax = std::max(figures_.jointErrorMax, jointError());
  }
  void check(SceneFigures &f) override {
    f.jointErrorEnd = jointError();
    // SCENES.md asks only to report the error; the check is that the body
    // is whole again once it has landed (the peak, at the impact, is a
    // reported figure).
    f.expectation = f.jointErrorEnd < 0.02;
    char text[120];
    std::snprintf(text, sizeof text, "joint error: max %.2f mm, end %.2f mm",
                  f.jointErrorMax * 1e3, f.jointErrorEnd * 1e3);
    f.detail = text;
  }
  McdModelID part_[10];
  MdtBSJointID joint_[9];
};

}  // namespace

std::unique_ptr<AnchorScene> MakeRagdoll() { return std::make_unique<RagdollScene>(); }

}  // namespace karma::scenes
