// meviewer_scene: draws one test scene through MeViewer for the golden
// image tests (golden/meviewer/<scene>/).
//
//   meviewer_scene -scene NAME [viewer options] [-trajectory FILE] [-platform reference]
//
// The golden driver adds -platform, -trajectory and -out; the trajectory
// holds no bodies (the scenes are still) and exists because every golden
// run writes one. Scenes: rectangle2d groundplane box cone cylinder sphere
// square torus frustum line nativeline custom wireframe lighting light_ambient
// light_directional light_point texture text help menu perfbar ase.
#include "MeViewer.h"

#include <karma/golden/KarmaTrajectory.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

RRender *rc = nullptr;
MeMatrix4 tm[4];

const float kRed[4] = {0.9f, 0.2f, 0.2f, 1}, kGreen[4] = {0.2f, 0.8f, 0.3f, 1}, kBlue[4] = {0.25f, 0.45f, 0.95f, 1};
const float kWhite[4] = {1, 1, 1, 1}, kYellow[4] = {0.95f, 0.85f, 0.2f, 1};

// Rotation about x by a, then about y by b, at (x, y, z): tilts z-axis
// primitives towards the camera so their caps show.
void Place(MeMatrix4 m, MeReal a, MeReal b, MeReal x, MeReal y, MeReal z) {
  const MeReal ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  // Rows are the images of the axes: Rx then Ry (row-vector convention).
  const MeReal rx[3][3] = {{1, 0, 0}, {0, ca, sa}, {0, -sa, ca}};
  const MeReal ry[3][3] = {{cb, 0, -sb}, {0, 1, 0}, {sb, 0, cb}};
  MeMatrix4TMMakeIdentity(m);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = rx[i][0] * ry[0][j] + rx[i][1] * ry[1][j] + rx[i][2] * ry[2][j];
  MeMatrix4TMSetPosition(m, x, y, z);
}

void Camera(MeReal dist, MeReal theta, MeReal phi) { RCameraSetView(rc, dist, theta, phi); }

// The perfbar scene's clock: every reading is 2 ms after the last, so each
// MeProfile start/end pair lasts 2 ms per clock reading between them.
double MEAPI StepClock(void *) {
  static double now = 0;
  return now += 2;
}

// Collision spans a nested section (3 readings: 6 ms), dynamics one pair (2 ms).
void MEAPI ProfiledTick(RRender *, void *) {
  MeProfileStartSection("collision");
  MeProfileStartSection("narrow phase");
  MeProfileEndSection("narrow phase");
  MeProfileEndSection("collision");
  MeProfileStartSection("dynamics");
  MeProfileEndSection("dynamics");
}

RMainLoopCallBack gTick = nullptr;

std::string gModel;  // -model FILE for the ase scene

bool Build(const std::string &s) {
  Place(tm[0], -1.1, 0.4, 0, 0, 0);
  Camera(5, 0.5, 0.35);
  if (s == "rectangle2d") {
    const float half[4] = {0.2f, 0.9f, 0.3f, 0.5f};
    RGraphic2DRectangleCreate(rc, 40, 40, 300, 200, kRed);
    RGraphic2DRectangleCreate(rc, 200, 150, 380, 280, half);
    RGraphic2DRectangleCreate(rc, 0, 440, 640, 40, kBlue);
  } else if (s == "groundplane") {
    RGraphicGroundPlaneCreate(rc, 10, 4, kGreen, -1);
    Camera(16, 0.3, 0.6);
  } else if (s == "box") {
    RGraphicBoxCreate(rc, 1.5, 1, 2, kRed, tm[0]);
  } else if (s == "cone") {
    RGraphicConeCreate(rc, 1, 1.2, 0.8, kYellow, tm[0]);
  } else if (s == "cylinder") {
    RGraphicCylinderCreate(rc, 0.8, 2, kBlue, tm[0]);
  } else if (s == "sphere") {
    RGraphicSphereCreate(rc, 1.3, kGreen, tm[0]);
  } else if (s == "square") {
    RGraphicSquareCreate(rc, 2, kRed, tm[0]);
  } else if (s == "torus") {
    RGraphicTorusCreate(rc, 0.8, 1.6, kYellow, tm[0]);
  } else if (s == "frustum") {
    RGraphicFrustumCreate(rc, 1.2, 0.6, -1, 1, 6, kBlue, tm[0]);
  } else if (s == "line") {
    AcmeReal o[3] = {-2, -1, 0}, e[3] = {2, 1, 0}, o2[3] = {-2, 1, 0}, e2[3] = {0, 0, 0};
    RGraphicLineCreate(rc, o, e, kRed, nullptr);
    RGraphic *l = RGraphicLineCreate(rc, o, e, kGreen, nullptr);
    RGraphicLineMoveEnds(l, o2, e2);  // the moved end must show
  } else if (s == "nativeline") {
    const AcmeReal s0[3] = {-2, -1, 0}, e0[3] = {2, 1, 0}, c[4] = {1, 1, 0, 1}, c2[4] = {0, 1, 1, 1};
    const AcmeReal s1[3] = {-2, 1, 0}, e1[3] = {2, -1, 0};
    RNLineCreate(rc, s0, e0, c, nullptr);
    RNativeLine *l = RNLineCreate(rc, s0, e0, c2, nullptr);
    RNLineMoveEnds(l, s1, e1);
  } else if (s == "custom") {
    // A pyramid from one strip and a separate triangle, through RConvertTriStripToTriList.
    RObjectVertex v[7] = {};
    const float p[7][3] = {{-1, -1, 1}, {0, 1, 0}, {1, -1, 1}, {0, 1, 0}, {1, -1, -1}, {-1, -1, -1}, {0, -1, 1}};
    for (int i = 0; i < 7; ++i) v[i].m_X = p[i][0], v[i].m_Y = p[i][1], v[i].m_Z = p[i][2], v[i].m_NZ = 1;
    int size[2] = {5, 2}, start[2] = {0, 5};
    RGraphic *g = RGraphicCreateEmpty(3);
    RConvertTriStripToTriList(g, v, size, start, 2);
    RGraphicSetColor(g, kYellow);
    RGraphicAddToList(rc, g, 0);
  } else if (s == "wireframe") {
    RGraphic *g = RGraphicSphereCreate(rc, 1.3, kWhite, tm[0]);
    g->m_pObject->m_bIsWireFrame = 1;
  } else if (s == "lighting") {
    // Coloured directional lights, a green ambient and an attenuated
    // point light between three white spheres over a plane.
    rc->m_rgbAmbientLightColor[0] = 0.05f, rc->m_rgbAmbientLightColor[1] = 0.15f, rc->m_rgbAmbientLightColor[2] = 0.05f;
    rc->m_DirectLight1.m_rgbDiffuse[0] = 0.8f, rc->m_DirectLight1.m_rgbDiffuse[1] = 0.2f,
    rc->m_DirectLight1.m_rgbDiffuse[2] = 0.2f;
    RLightSwitchOff(rc, kRDirect2);
    RLightSwitchOn(rc, kRPoint);
    rc->m_PointLight.m_Position[0] = 0, rc->m_PointLight.m_Position[1] = 1.5f, rc->m_PointLight.m_Position[2] = 0;
    rc->m_PointLight.m_rgbDiffuse[0] = 0.3f, rc->m_PointLight.m_rgbDiffuse[1] = 0.4f,
    rc->m_PointLight.m_rgbDiffuse[2] = 1;
    rc->m_PointLight.m_AttenuationConstant = 0.2f;
    rc->m_PointLight.m_AttenuationQuadratic = 0.3f;
    Place(tm[1], 0, 0, -2, 0, 0);
    Place(tm[2], 0, 0, 2, 0, 0);
    Place(tm[3], 0, 0, 0, 0, -2);
    for (int i = 1; i < 4; ++i) RGraphicSphereCreate(rc, 0.8, kWhite, tm[i]);
    RGraphicGroundPlaneCreate(rc, 10, 8, kWhite, -0.8);
    Camera(7, 0.2, 0.5);
  } else if (s == "light_ambient" || s == "light_directional" || s == "light_point") {
    // One light mode at a time on a white sphere over a plane.
    RLightSwitchOff(rc, kRDirect1);
    RLightSwitchOff(rc, kRDirect2);
    if (s == "light_ambient") {
      rc->m_rgbAmbientLightColor[0] = 0.6f, rc->m_rgbAmbientLightColor[1] = 0.5f, rc->m_rgbAmbientLightColor[2] = 0.2f;
    } else {
      RLightSwitchOff(rc, kRAmbient);
    }
    if (s == "light_directional") {
      RLightSwitchOn(rc, kRDirect1);
      rc->m_DirectLight1.m_Direction[0] = 1, rc->m_DirectLight1.m_Direction[1] = -1,
      rc->m_DirectLight1.m_Direction[2] = -0.5f;
      RLightSwitchOn(rc, kRDirect2);
      rc->m_DirectLight2.m_rgbDiffuse[0] = 0.1f, rc->m_DirectLight2.m_rgbDiffuse[1] = 0.1f,
      rc->m_DirectLight2.m_rgbDiffuse[2] = 0.6f;
      rc->m_DirectLight2.m_Direction[0] = -1, rc->m_DirectLight2.m_Direction[1] = 0.2f,
      rc->m_DirectLight2.m_Direction[2] = 0;
    }
    if (s == "light_point") {
      RLightSwitchOn(rc, kRPoint);
      rc->m_PointLight.m_Position[0] = 1.5f, rc->m_PointLight.m_Position[1] = 0.5f,
      rc->m_PointLight.m_Position[2] = 1.5f;
      rc->m_PointLight.m_AttenuationConstant = 0.5f;
      rc->m_PointLight.m_AttenuationLinear = 0.2f;
      rc->m_PointLight.m_AttenuationQuadratic = 0.2f;
    }
    RGraphicSphereCreate(rc, 1, kWhite, nullptr);
    RGraphicGroundPlaneCreate(rc, 8, 8, kWhite, -1);
    Camera(6, 0.3, 0.45);
  } else if (s == "texture") {
    char checker[] = "checkerboard";
    RGraphic *plane = RGraphicGroundPlaneCreate(rc, 8, 2, kWhite, -1);
    RGraphicSetTexture(rc, plane, checker);
    Place(tm[1], -0.3, 0.5, 0, 0.2, 0);
    RGraphicSetTexture(rc, RGraphicBoxCreate(rc, 1.5, 1.5, 1.5, kYellow, tm[1]), checker);
    Camera(6, 0.4, 0.5);
  } else if (s == "text") {
    char l1[] = "MeViewer text at 640x480: ABCDEFGHIJKLMNOPQRSTUVWXYZ";
    char l2[] = "abcdefghijklmnopqrstuvwxyz 0123456789 !\"#$%&'()*+,-./:;<=>?@[\\]^_`{|}~";
    char l3[] = "Two lines\nin one graphic";
    RGraphicTextCreate(rc, l1, 10, 10, kWhite);
    RGraphicTextCreate(rc, l2, 10, 30, kYellow);
    RGraphicTextCreate(rc, l3, 10, 60, kGreen);
    RGraphic2DRectangleCreate(rc, 0, 400, 640, 80, kBlue);
    char l4[] = "text over a rectangle";
    RGraphicTextCreate(rc, l4, 20, 430, kWhite);
  } else if (s == "help") {
    // RainbowChain's help, shown as the guide's program shows it.
    std::strcpy(rc->m_AppName, "RainbowChain");
    char l0[] = "$ACTION1 - toggle options menu", l1[] = "$ACTION2 - reset", l2[] = "$MOUSE - apply mouse force";
    char *help[3] = {l0, l1, l2};
    RGraphicSphereCreate(rc, 1.3, kGreen, tm[0]);
    RRenderCreateUserHelp(rc, help, 3);
    RRenderToggleUserHelp(rc);
  } else if (s == "perfbar") {
    RGraphicSphereCreate(rc, 1.3, kGreen, tm[0]);
    MeProfileSetClock(StepClock, nullptr);
    RPerformanceBarCreate(rc);
    gTick = ProfiledTick;
  } else if (s == "ase") {
    char checker[] = "checkerboard";
    Place(tm[1], -1.4, 0.6, 0, -0.3, 0);
    RGraphic *g = RGraphicLoadASE(rc, gModel.data(), 1.2, 1.2, 1.2, kWhite, tm[1]);
    if (!g) return false;
    RGraphicSetTexture(rc, g, checker);
  } else if (s == "menu") {
    RGraphicSphereCreate(rc, 1.3, kGreen, tm[0]);
    RMenu *menu = RMenuCreate(rc, "Options");
    RMenu *more = RMenuCreate(rc, "More");
    RMenuAddToggleEntry(menu, "gravity", nullptr, 1);
    RMenuAddValueEntry(menu, "friction", nullptr, 2, 0, 0.25, 0.5);
    RMenuAddSubmenuEntry(menu, "more", more);
    RRenderSetDefaultMenu(rc, menu);
  } else {
    return false;
  }
  return true;
}

void MEAPI_CDECL Cleanup() { RRenderContextDestroy(rc); }

}  // namespace

int main(int argc, const char *argv[]) {
  MeCommandLineOptions *opts = MeCommandLineOptionsCreate(argc, argv);
  rc = RRenderContextCreate(opts, nullptr, 1);
  const char *scene = MeCommandLineOptionsGetString(opts, "-scene", 1);
  const char *trajectoryPath = MeCommandLineOptionsGetString(opts, "-trajectory", 1);
  const char *platform = MeCommandLineOptionsGetString(opts, "-platform", 1);
  const char *model = MeCommandLineOptionsGetString(opts, "-model", 1);
  gModel = model ? model : "";
  const std::string sceneName = scene ? scene : "";
  const std::string path = trajectoryPath ? trajectoryPath : "";
  const std::string backend = platform ? platform : "reference";
  MeCommandLineOptionsDestroy(opts);
  if (!rc) return 1;
  if (!Build(sceneName)) {
    std::fprintf(stderr, "meviewer_scene: unknown scene '%s'\n", sceneName.c_str());
    RRenderContextDestroy(rc);
    return 2;
  }
  // An empty trajectory: one frame, no bodies.
  KarmaTrajectoryInfo info = {"meviewer", sceneName.c_str(), backend.c_str(), "one still frame", (MeReal)1 / 60, 0};
  KarmaTrajectoryWriter *w = KarmaTrajectoryWriterCreate(path.empty() ? nullptr : path.c_str(), &info);
  const bool ok = w && KarmaTrajectoryWriterBeginFrame(w, 0, 0) && KarmaTrajectoryWriterEndFrame(w);
  if (!KarmaTrajectoryWriterDestroy(w) || !ok) {
    std::fprintf(stderr, "meviewer_scene: cannot write the trajectory %s\n", path.c_str());
    RRenderContextDestroy(rc);
    return 1;
  }
  std::atexit(Cleanup);
  RRun(rc, gTick, nullptr);
}
