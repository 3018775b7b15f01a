/* sample.c: see sample.h. */
#include "sample.h"

#include "tutorial_record.h"

#include <stdio.h>
#include <stdlib.h>

#define SAMPLE_RECORD_EVERY 10
#define SAMPLE_MAX_RECORDED 64

static RRender *rc_;
static MstUniverseID universe_;
static MdtWorldID world_;
static TutorialRecord *record_;
static MdtBodyID recorded_[SAMPLE_MAX_RECORDED];
static int recordedCount_;
static MeReal step_;
static SampleHook before_, after_;

static void MEAPI_CDECL SampleCleanup(void) {
  if (universe_) MstUniverseDestroy(universe_);
  if (world_) MdtWorldDestroy(world_);
  RRenderContextDestroy(rc_);
  universe_ = NULL, world_ = NULL, rc_ = NULL;
}

RRender *SampleOpen(int argc, const char *argv[], const char *caption) {
  const float white[4] = {1, 1, 1, 1};
  MeCommandLineOptions *options = MeCommandLineOptionsCreate(argc, argv);
  rc_ = RRenderContextCreate(options, 0, 1);
  MeCommandLineOptionsDestroy(options);
  if (!rc_) exit(1);
  /* Registered before the record's handler, so it runs after it. */
  atexit(SampleCleanup);
  if (caption) RGraphicTextCreate(rc_, (char *)caption, 10, 10, white);
  return rc_;
}

MstUniverseID SampleUniverse(int instances) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  if (instances > 0) sizes.collisionGeometryInstancesMaxCount = instances;
  universe_ = MstUniverseCreate(&sizes);
  if (!universe_) exit(1);
  return universe_;
}

MdtWorldID SampleWorld(int bodies, int constraints) {
  world_ = MdtWorldCreate(bodies, constraints, 1, 1);
  if (!world_) exit(1);
  return world_;
}

RGraphic *SampleGround(RRender *rc, MeReal side, MeReal y) {
  const float white[4] = {1, 1, 1, 1};
  RGraphic *g = RGraphicGroundPlaneCreate(rc, side, 8, white, y);
  RGraphicSetTexture(rc, g, "checkerboard");
  return g;
}

static void PutVertex(RObjectVertex *v, const MeReal *p, const MeVector3 n) {
  v->m_X = (float)p[0], v->m_Y = (float)p[1], v->m_Z = (float)p[2];
  v->m_NX = (float)n[0], v->m_NY = (float)n[1], v->m_NZ = (float)n[2];
  v->m_U = 0, v->m_V = 0;
}

RGraphic *SampleConvexMeshGraphic(RRender *rc, McdConvexMeshID mesh, const float color[4], MeMatrix4Ptr tm) {
  const int faces = McdConvexMeshGetPolygonCount(mesh);
  int f, k, triangles = 0, n = 0;
  RGraphic *g;
  for (f = 0; f < faces; ++f) triangles += McdConvexMeshGetPolygonVertexCount(mesh, f) - 2;
  g = RGraphicCreateEmpty(3 * triangles);
  if (!g) return NULL;
  /* Each face as a fan from its first corner (counter-clockwise outside). */
  for (f = 0; f < faces; ++f) {
    MeVector3 normal;
    const MeReal *first = McdConvexMeshGetVertex(mesh, McdConvexMeshGetPolygonVertexIndex(mesh, f, 0));
    McdConvexMeshGetPolygonNormal(mesh, f, normal);
    for (k = 1; k + 1 < McdConvexMeshGetPolygonVertexCount(mesh, f); ++k) {
      PutVertex(&g->m_pVertices[n++], first, normal);
      PutVertex(&g->m_pVertices[n++], McdConvexMeshGetVertex(mesh, McdConvexMeshGetPolygonVertexIndex(mesh, f, k)),
                normal);
      PutVertex(&g->m_pVertices[n++], McdConvexMeshGetVertex(mesh, McdConvexMeshGetPolygonVertexIndex(mesh, f, k + 1)),
                normal);
    }
  }
  g->m_pObject->m_nNumVertices = n;
  RGraphicSetColor(g, color);
  RGraphicSetTransformPtr(g, tm);
  RGraphicAddToList(rc, g, 0);
  return g;
}

void SampleCamera(RRender *rc, MeReal x, MeReal y, MeReal z, MeReal distance, MeReal theta, MeReal phi) {
  AcmeVector3 lookAt;
  lookAt[0] = x, lookAt[1] = y, lookAt[2] = z;
  RCameraSetLookAt(rc, lookAt);
  RCameraSetView(rc, distance, theta, phi);
}

void SampleBoxInertia(MeReal m, const MeReal size[3], MeMatrix3 I) {
  int i, j;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) I[i][j] = 0;
  I[0][0] = m / 12 * (size[1] * size[1] + size[2] * size[2]);
  I[1][1] = m / 12 * (size[0] * size[0] + size[2] * size[2]);
  I[2][2] = m / 12 * (size[0] * size[0] + size[1] * size[1]);
}

void SampleRecordBody(MdtBodyID body) {
  if (recordedCount_ < SAMPLE_MAX_RECORDED) recorded_[recordedCount_++] = body;
}

static void MEAPI SampleTick(RRender *rc, void *userdata) {
  (void)rc, (void)userdata;
  if (before_) before_();
  if (universe_)
    MstUniverseStep(universe_, step_);
  else
    MdtWorldStep(world_, step_);
  TutorialRecordStep(record_);
  if (after_) after_();
}

void SampleRun(int argc, const char *argv[], const char *name, MeReal h, SampleHook beforeStep, SampleHook afterStep) {
  int i;
  step_ = h, before_ = beforeStep, after_ = afterStep;
  record_ = TutorialRecordCreate(argc, (char **)argv, "samples", name, h, SAMPLE_RECORD_EVERY);
  if (!record_) exit(1);
  for (i = 0; i < recordedCount_; ++i) TutorialRecordAddBody(record_, recorded_[i]);
  TutorialRecordStart(record_);
  RRun(rc_, SampleTick, 0);
}
