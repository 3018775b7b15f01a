// registry.cpp: registering geometry types in a framework, and the bundles
// (primitives, sphere-box-plane) of types and interactions.
#include "mcd_internal.h"

using namespace karma::mcd;

namespace {

void Register(McdFramework *fw, int type, const GeometryType &record, const char *fn) {
  ME_REQUIRE_ARG(fw != nullptr, fn, "framework is NULL");
  fw->types[type] = &record;
}

}  // namespace

extern "C" {

void MEAPI McdSphereRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeSphere, kSphereType, "McdSphereRegisterType");
}
void MEAPI McdBoxRegisterType(McdFrameworkID fw) { Register(fw, kMcdGeometryTypeBox, kBoxType, "McdBoxRegisterType"); }
void MEAPI McdCylinderRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeCylinder, kCylinderType, "McdCylinderRegisterType");
}
void MEAPI McdPlaneRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypePlane, kPlaneType, "McdPlaneRegisterType");
}
void MEAPI McdSphylRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeSphyl, kSphylType, "McdSphylRegisterType");
}
void MEAPI McdTriangleListRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeTriangleList, kTriangleListType, "McdTriangleListRegisterType");
}
void MEAPI McdConvexMeshRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeConvexMesh, kConvexMeshType, "McdConvexMeshRegisterType");
}
void MEAPI McdAggregateRegisterType(McdFrameworkID fw) {
  Register(fw, kMcdGeometryTypeAggregate, kAggregateType, "McdAggregateRegisterType");
}

void MEAPI McdPrimitivesRegisterTypes(McdFrameworkID fw) {
  ME_REQUIRE_ARG(fw != nullptr, "McdPrimitivesRegisterTypes", "framework is NULL");
  McdSphereRegisterType(fw);
  McdBoxRegisterType(fw);
  McdCylinderRegisterType(fw);
  McdPlaneRegisterType(fw);
  McdSphylRegisterType(fw);
  McdTriangleListRegisterType(fw);
  McdConvexMeshRegisterType(fw);
  McdAggregateRegisterType(fw);
}

// Every interaction family built so far. The nearfield work adds its
// families' Register calls here (each skips pairs whose types are absent).
void MEAPI McdPrimitivesRegisterInteractions(McdFrameworkID fw) {
  ME_REQUIRE_ARG(fw != nullptr, "McdPrimitivesRegisterInteractions", "framework is NULL");
  McdSphereSphereRegisterInteraction(fw);
  McdSpherePlaneRegisterInteraction(fw);
  McdBoxPlaneRegisterInteraction(fw);
  // Analytic primitive pairs (nearfield/: sphere, box, cylinder, sphyl, plane).
  McdSphereBoxRegisterInteraction(fw);
  McdSphereCylinderRegisterInteraction(fw);
  McdSphereSphylRegisterInteraction(fw);
  McdBoxBoxRegisterInteraction(fw);
  McdSphylSphylRegisterInteraction(fw);
  McdSphylBoxRegisterInteraction(fw);
  McdCylinderPlaneRegisterInteraction(fw);
  McdSphylPlaneRegisterInteraction(fw);
  // General convex pairs through libccd with contact manifolds
  // (nearfield/convex_*.cpp), aggregates child by child
  // (nearfield/aggregate_any.cpp) and triangle lists (nearfield/trilist.cpp).
  McdConvexMeshSphereRegisterInteraction(fw);
  McdConvexMeshBoxRegisterInteraction(fw);
  McdConvexMeshCylinderRegisterInteraction(fw);
  McdConvexMeshSphylRegisterInteraction(fw);
  McdConvexMeshConvexMeshRegisterInteraction(fw);
  McdConvexMeshPlaneRegisterInteraction(fw);
  McdBoxCylinderRegisterInteraction(fw);
  McdCylinderCylinderRegisterInteraction(fw);
  McdCylinderSphylRegisterInteraction(fw);
  McdAggregateRegisterInteractions(fw);
  McdSphereTriangleListRegisterInteraction(fw);
  McdBoxTriangleListRegisterInteraction(fw);
  McdCylinderTriangleListRegisterInteraction(fw);
  McdSphylTriangleListRegisterInteraction(fw);
  McdConvexMeshTriangleListRegisterInteraction(fw);
}

int MEAPI McdPrimitivesGetTypeCount(void) { return kMcdGeometryBuiltInTypes; }

void MEAPI McdSphereBoxPlaneRegisterTypes(McdFrameworkID fw) {
  ME_REQUIRE_ARG(fw != nullptr, "McdSphereBoxPlaneRegisterTypes", "framework is NULL");
  McdSphereRegisterType(fw);
  McdBoxRegisterType(fw);
  McdPlaneRegisterType(fw);
}

void MEAPI McdSphereBoxPlaneRegisterInteractions(McdFrameworkID fw) {
  ME_REQUIRE_ARG(fw != nullptr, "McdSphereBoxPlaneRegisterInteractions", "framework is NULL");
  McdSphereSphereRegisterInteraction(fw);
  McdSpherePlaneRegisterInteraction(fw);
  McdBoxPlaneRegisterInteraction(fw);
  McdSphereBoxRegisterInteraction(fw);
  McdBoxBoxRegisterInteraction(fw);
}

MeBool MEAPI McdFrameworkIsTypeRegistered(McdFrameworkID fw, int typeId) {
  if (!fw || typeId < 0 || typeId >= fw->typeMax) return 0;
  return fw->types[typeId] != nullptr;
}

const char *MEAPI McdFrameworkGetTypeName(McdFrameworkID fw, int typeId) {
  if (!McdFrameworkIsTypeRegistered(fw, typeId)) return nullptr;
  return fw->types[typeId]->name;
}

}  // extern "C"
