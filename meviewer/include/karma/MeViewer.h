/* MeViewer.h: the Karma demo renderer (Appendix B of the guide).
 *
 * A program creates a render context from its command line, creates
 * graphics pointed at the transforms it simulates, and hands control to
 * RRun, which loops { input, tick, draw } until the user quits, -frames N
 * frames have been drawn, or RRenderQuit is called, and then ends the
 * program through exit() (so cleanup registered with atexit runs; RRun never
 * returns):
 *
 *   MeCommandLineOptions *opts = MeCommandLineOptionsCreate(argc, argv);
 *   RRender *rc = RRenderContextCreate(opts, 0, 1);
 *   MeCommandLineOptionsDestroy(opts);
 *   if (!rc) return 1;
 *   RGraphicSphereCreate(rc, 1, red, MdtBodyGetTransformPtr(body));
 *   atexit(cleanup);            (cleanup calls RRenderContextDestroy(rc))
 *   RRun(rc, tick, 0);
 *
 * Backends, chosen on the command line (`prog -help` lists every option):
 *   -gl      (default; -d3d is a synonym) OpenGL rendered offscreen through OSMesa
 *   -null    the loop runs, nothing is drawn
 *   -bench   as -null, and per-frame timing statistics are printed at exit
 *   -profile draws, and prints a per-phase timing table at exit (with the
 *            platform backend the dynamics worlds ran on)
 * Output: -frames N, -out DIR (DIR/frame_00000.png ...), -every K, -bmp,
 * -size WxH (default 640x480), -video FILE (with ffmpeg). Input: -keys
 * SCRIPT, -keyfile FILE (scripted key presses and mouse moves).
 * -platform NAME makes that backend (MdtPlatform.h) the default of the
 * dynamics worlds created after the context; an unknown name fails the
 * context's creation. The option stays in the list for the program.
 *
 * Functions taking an RRender* accept NULL with a warning and do nothing
 * (returning NULL / -1 / 1 where they return something). */
#ifndef KARMA_MEVIEWER_H
#define KARMA_MEVIEWER_H

#include "MeGlobals.h"
#include "MeViewerTypes.h"

ME_EXTERN_C_BEGIN

/* ---- render contexts and the main loop --------------------------------- */

/* Reads the viewer's options from `options`, then from `overrideOptions`
 * (which win), removing them from both when `eat` is true; fills the
 * context with defaults and starts the backend. Returns NULL (with a
 * message) if an option is malformed, the output directory cannot be
 * written, or the backend cannot start. -help prints the options and exits
 * the program with status 0. */
MEPUBLIC RRender *MEAPI RRenderContextCreate(MeCommandLineOptions *options, MeCommandLineOptions *overrideOptions,
                                             MeBool eat);
/* Frees the context, its graphics in both lists, native lines and
 * textures. NULL is accepted. Returns 0. */
MEPUBLIC int MEAPI RRenderContextDestroy(RRender *rc);
/* Asks RRun to stop before the next frame. */
MEPUBLIC void MEAPI RRenderQuit(RRender *rc);
/* Runs the loop (see the top of this file); ends the program with exit(0),
 * or exit(1) when rc is NULL. */
MEPUBLIC void MEAPI RRun(RRender *rc, RMainLoopCallBack tick, void *userdata);
/* RRun for a tick without user data (see RRun's forms below). */
MEPUBLIC void MEAPI RRunNoData(RRender *rc, RMainLoopCallBackNoData tick, void *userdata);

/* ---- render lists ------------------------------------------------------ */

MEPUBLIC void MEAPI RGraphicAddToList(RRender *rc, RGraphic *rg, int is2D);
MEPUBLIC void MEAPI RGraphicRemoveFromList(RRender *rc, RGraphic *rg, int is2D);

/* ---- primitives (each is added to the context's 3D list, text and
 * rectangles to the 2D list; NULL on failure) ----------------------------- */

/* x, y: left and top edge in 2D units. */
MEPUBLIC RGraphic *MEAPI RGraphic2DRectangleCreate(RRender *rc, AcmeReal x, AcmeReal y, AcmeReal width, AcmeReal height,
                                                   const float color[4]);
/* A square in x-z of side `length` at height y_pos, cut into `triangles`
 * cells per side (two triangles each); textures span it once. */
MEPUBLIC RGraphic *MEAPI RGraphicGroundPlaneCreate(RRender *rc, AcmeReal length, int triangles, const float color[4],
                                                   AcmeReal y_pos);
/* Centred at the origin, sides x, y, z. */
MEPUBLIC RGraphic *MEAPI RGraphicBoxCreate(RRender *rc, AcmeReal x, AcmeReal y, AcmeReal z, const float color[4],
                                           MeMatrix4Ptr matrix);
/* Axis z: apex at z = uheight, base (radius `radius`) at z = -lheight. */
MEPUBLIC RGraphic *MEAPI RGraphicConeCreate(RRender *rc, AcmeReal radius, AcmeReal uheight, AcmeReal lheight,
                                            const float color[4], MeMatrix4Ptr matrix);
/* Axis z, from -height/2 to height/2. */
MEPUBLIC RGraphic *MEAPI RGraphicCylinderCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                                MeMatrix4Ptr matrix);
MEPUBLIC RGraphic *MEAPI RGraphicSphereCreate(RRender *rc, AcmeReal radius, const float color[4], MeMatrix4Ptr matrix);
/* In the x-y plane, centred, facing +z. */
MEPUBLIC RGraphic *MEAPI RGraphicSquareCreate(RRender *rc, AcmeReal side, const float color[4], MeMatrix4Ptr matrix);
/* About the z axis; the surface spans distances innerRadius..outerRadius
 * from the axis (tube radius (outer - inner) / 2). */
MEPUBLIC RGraphic *MEAPI RGraphicTorusCreate(RRender *rc, AcmeReal innerRadius, AcmeReal outerRadius,
                                             const float color[4], MeMatrix4Ptr matrix);
/* Axis z, a `sides`-gon of radius bottomRadius at z = bottom to one of
 * topRadius at z = top, both ends capped. */
MEPUBLIC RGraphic *MEAPI RGraphicFrustumCreate(RRender *rc, AcmeReal bottomRadius, AcmeReal topRadius, AcmeReal bottom,
                                               AcmeReal top, int sides, const float color[4], MeMatrix4Ptr matrix);
/* A line as an RGraphic: one degenerate wireframe triangle (origin, end,
 * end). Move it with RGraphicLineMoveEnds. */
MEPUBLIC RGraphic *MEAPI RGraphicLineCreate(RRender *rc, AcmeReal *origin, AcmeReal *end, const float color[4],
                                            MeMatrix4Ptr matrix);
/* Returns 0, or 1 with a warning if lineG is not a line made by RGraphicLineCreate. */
MEPUBLIC int MEAPI RGraphicLineMoveEnds(RGraphic *lineG, AcmeReal *origin, AcmeReal *end);
/* A line the graphics library draws itself; kept in the context. */
MEPUBLIC RNativeLine *MEAPI RNLineCreate(RRender *const rc, const AcmeReal start[3], const AcmeReal end[3],
                                         const AcmeReal color[4], const MeVector4 *const matrix);
MEPUBLIC void MEAPI RNLineMoveEnds(RNativeLine *const line, const AcmeReal start[3], const AcmeReal end[3]);
/* Text in the 2D list, textured with the built-in "font": x, y are the left
 * and top edge in 2D units; '\n' starts a new line. */
MEPUBLIC RGraphic *MEAPI RGraphicTextCreate(RRender *rc, char *text, AcmeReal x, AcmeReal y, const float color[4]);

/* ---- objects ------------------------------------------------------------ */

/* Room for numVertices vertices (none in use yet: m_nNumVertices = 0),
 * white, untextured, solid, no transform; in no list. */
MEPUBLIC RGraphic *MEAPI RGraphicCreateEmpty(int numVertices);
/* Frees a graphic that is in no list (its header and vertices too). */
MEPUBLIC void MEAPI RGraphicDestroy(RGraphic *rg);
/* Removes rg from the given list and frees it. */
MEPUBLIC void MEAPI RGraphicDelete(RRender *rc, RGraphic *rg, int is2D);
MEPUBLIC void MEAPI RGraphicSetTransformPtr(RGraphic *g, MeMatrix4Ptr matrix);
/* Ambient and diffuse become color; emissive and specular become 0. */
MEPUBLIC void MEAPI RGraphicSetColor(RGraphic *g, const float color[4]);
/* The ambient colour. */
MEPUBLIC void MEAPI RGraphicGetColor(RGraphic *g, float color[4]);
/* Sets or clears the wireframe flag. */
MEPUBLIC void MEAPI RGraphicSetWireframe(RGraphic *g, MeBool wireframe);
/* Appends the triangles of the strips to rg's list (growing the
 * allocation as needed), alternate triangles reversed so every triangle
 * keeps the strip's winding. rg->m_pVertices may move. */
MEPUBLIC void MEAPI RConvertTriStripToTriList(RGraphic *rg, RObjectVertex *strips, int *stripSize, int *stripStart,
                                              int numStrips);

/* ---- object files (ASE) ------------------------------------------------------- */

/* Loads the meshes of an ASE file (3ds Max ASCII export: *MESH_VERTEX_LIST,
 * *MESH_FACE_LIST, optional *MESH_TVERTLIST / *MESH_TFACELIST texture
 * coordinates and *MESH_VERTEXNORMAL normals; materials are ignored),
 * positions multiplied by the scales, into one graphic in the 3D list.
 * The file is found like a texture (the search path), by its full name.
 * NULL with a message for a missing or malformed file. */
MEPUBLIC RGraphic *MEAPI RGraphicLoadASE(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                                         const float color[4], MeMatrix4Ptr matrix);
/* As RGraphicLoadASE, after normalising the object: centred on its bounding
 * box, each side scaled to length 2 (or, with bKeepAspectRatio, the longest
 * side to 2 and the others in proportion), then multiplied by the scales;
 * put in the 2D list when is2D. */
MEPUBLIC RGraphic *MEAPI RGraphicCreate(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                                        const AcmeReal color[4], MeMatrix4Ptr matrix, int is2D, int bKeepAspectRatio);

/* ---- textures ------------------------------------------------------------ */

/* The ID for a texture file name (a name seen before keeps its ID), or -1
 * when all R_MAX_TEXTURES IDs are taken. Files load when RRun starts (or
 * the next frame, for names added later). */
MEPUBLIC int MEAPI RRenderTextureCreate(RRender *rc, char *filename);
/* Gives rg the texture `filename` (no extension: ".bmp" is added and the
 * search path of docs/ARCHITECTURE.md followed). Returns the ID, or -1
 * (and rg is untextured) when all IDs are taken. */
MEPUBLIC int MEAPI RGraphicSetTexture(RRender *rc, RGraphic *rg, char *filename);
/* The older names the guide's prose uses for the two functions above (same
 * arguments, same result): RCreateTextureID is RRenderTextureCreate,
 * RSetTexture is RGraphicSetTexture. As the guide says, RSetTexture with a
 * name that has no file leaves the graphic untextured (after one message);
 * setting its RObjectHeader's m_nTextureID to -1 does it without the look-up. */
MEPUBLIC int MEAPI RCreateTextureID(RRender *rc, char *filename);
MEPUBLIC int MEAPI RSetTexture(RRender *rc, RGraphic *rg, char *filename);

/* ---- camera -------------------------------------------------------------- */

MEPUBLIC void MEAPI RCameraSetLookAt(RRender *rc, const AcmeVector3 lookAt);
MEPUBLIC void MEAPI RCameraGetLookAt(RRender *rc, AcmeVector3 camlookat);
/* dist is clamped to >= 0.01, theta wrapped into [-pi, pi], phi clamped
 * into [-pi/2, pi/2]. */
MEPUBLIC void MEAPI RCameraSetView(RRender *rc, AcmeReal dist, AcmeReal theta, AcmeReal phi);
MEPUBLIC void MEAPI RCameraGetPosition(RRender *rc, AcmeVector3 campos);
MEPUBLIC void MEAPI RCameraZoom(RRender *rc, AcmeReal dist);
/* Pans move the look-at point and the camera together along the camera's
 * right (X), up (Y) and forward (Z, towards the look-at) directions. */
MEPUBLIC void MEAPI RCameraPanX(RRender *rc, AcmeReal dist);
MEPUBLIC void MEAPI RCameraPanY(RRender *rc, AcmeReal dist);
MEPUBLIC void MEAPI RCameraPanZ(RRender *rc, AcmeReal dist);
MEPUBLIC void MEAPI RCameraRotateAngle(RRender *rc, AcmeReal d_theta);
MEPUBLIC void MEAPI RCameraRotateElevation(RRender *rc, AcmeReal d_phi);
MEPUBLIC void MEAPI RCameraUpdate(RRender *rc);

/* ---- lights -------------------------------------------------------------- */

MEPUBLIC void MEAPI RLightSwitchOn(RRender *rc, RRenderLight light);
MEPUBLIC void MEAPI RLightSwitchOff(RRender *rc, RRenderLight light);
/* The guide names these functions both RLightSwitchOn/Off and
 * RSwitchLightOn/Off; both spellings work. */
MEPUBLIC void MEAPI RSwitchLightOn(RRender *rc, RRenderLight light);
MEPUBLIC void MEAPI RSwitchLightOff(RRender *rc, RRenderLight light);

/* ---- controls ------------------------------------------------------------- */

/* Keys (there is no window: -keys / -keyfile scripts press them; see
 * docs/ARCHITECTURE.md, "Key scripts"):
 *   Up Down Left Right      the arrow keys       Up2 Down2 Left2 Right2   w s a d
 *   Action0 Space  Action1 Tab  Action2 Return  Action3 x  Action4 c  Action5 v
 *   Escape quits (or closes an open menu); Action1's key opens the default
 *   menu when the program has no Action1 callback. */
MEPUBLIC void MEAPI RRenderSetUpCallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetUp2CallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetDownCallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetDown2CallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetLeftCallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetLeft2CallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetRightCallBack(RRender *rc, RButtonPressCallBack func);
MEPUBLIC void MEAPI RRenderSetRight2CallBack(RRender *rc, RButtonPressCallBack func);
/* N in 0..R_MAX_ACTIONS-1; func gets userdata. */
MEPUBLIC void MEAPI RRenderSetActionNCallBack(RRender *rc, int N, RButtonPressCallBack func, void *userdata);
/* Makes the printable character `key` press action N (instead of its default key). */
MEPUBLIC void MEAPI RRenderSetActionNKey(RRender *rc, const unsigned int N, const char key);
MEPUBLIC void MEAPI RRenderSetMouseCallBack(RRender *rc, RMouseCallBack func, void *userdata);

/* ---- menus ------------------------------------------------------------------ */

/* A menu is drawn over the scene while displayed. Keys while it is open:
 * Up / Down move the highlight; Left / Right step a value entry down / up
 * by its increment within [lo, hi], or flip a toggle; Return flips a
 * toggle or opens a submenu; Escape goes back to the parent menu or closes
 * the menu; Action1's key closes it. Callbacks run with the new value on
 * every change. The context frees menus still alive when it is destroyed. */
MEPUBLIC RMenu *MEAPI RMenuCreate(RRender *rc, const char *name);
MEPUBLIC void MEAPI RMenuDestroy(RMenu *rm);
MEPUBLIC void MEAPI RRenderSetDefaultMenu(RRender *rc, RMenu *menu);
MEPUBLIC void MEAPI RMenuDisplay(RMenu *rm);
MEPUBLIC void MEAPI RMenuAddToggleEntry(RMenu *rm, const char *name, RMenuToggleCallback func, MeBool defaultValue);
MEPUBLIC void MEAPI RMenuAddValueEntry(RMenu *rm, const char *name, RMenuValueCallback func, MeReal hi, MeReal lo,
                                       MeReal increment, MeReal defaultValue);
MEPUBLIC void MEAPI RMenuAddSubmenuEntry(RMenu *rm, const char *name, RMenu *submenu);

/* ---- performance -------------------------------------------------------------- */

/* Adds a bar along the bottom of the screen showing, for the last frame,
 * the time in the MeProfile sections "collision" and "dynamics" (which the
 * program's tick times, as Mst does), the viewer's rendering, and the idle
 * rest of a 1/60 s frame. While a bar exists RRun opens an MeProfile frame
 * per loop iteration and times "render" itself. Returns the context's bar
 * (one per context, freed with it), or NULL if rc is NULL. */
MEPUBLIC RPerformanceBar *MEAPI RPerformanceBarCreate(RRender *rc);

/* ---- accuracy -------------------------------------------------------------------- */

/* What the -accuracy overlay shows and -profile prints: figures of the
 * simulation after the last tick, from a source the program sets (the
 * viewer knows no physics; MeViewerAccuracy.h's probe computes them from
 * a dynamics world). */
typedef struct RAccuracyFigures {
  MeReal jointError;  /* largest joint gap: a joint's point as carried by each body, m */
  MeReal penetration; /* deepest contact penetration, m */
  MeReal energyDrift; /* kinetic + potential energy now minus at the first frame, J */
  MeReal residual;    /* the solver's largest residual in the last step */
} RAccuracyFigures;
typedef void(MEAPI *RAccuracySource)(RAccuracyFigures *figures, void *data);

/* Sets the source RRun reads after every tick when -accuracy or -profile
 * is given (NULL removes it). With -accuracy the figures are drawn beside
 * the performance bar; with -profile they are printed at exit for each
 * quarter of the run. */
MEPUBLIC void MEAPI RRenderSetAccuracySource(RRender *rc, RAccuracySource source, void *data);
/* 1 when the command line asked for the accuracy overlay (-accuracy). */
MEPUBLIC MeBool MEAPI RRenderAccuracyRequested(const RRender *rc);

/* ---- help and text utilities ----------------------------------------------- */

/* Copies text_in to text_out (at most outbuffersize bytes, always
 * terminated), replacing variables: $UP $DOWN $LEFT $RIGHT, $UP2 $DOWN2
 * $LEFT2 $RIGHT2, $ACTION0..$ACTION5 (the keys that press them), $MOUSE,
 * $APPNAME (rc->m_AppName). A variable is '$' and the longest run of
 * capitals and digits after it; unknown ones are copied unchanged. */
MEPUBLIC void MEAPI RParseText(RRender *rc, char *text_in, char *text_out, int outbuffersize);
/* Builds the help panel from `arraySize` lines, each put through RParseText. */
MEPUBLIC void MEAPI RRenderCreateUserHelp(RRender *rc, char *help[], int arraySize);
/* Shows or hides the help panel and pauses or resumes the simulation: while
 * the help shows, RRun draws but does not call the tick. F1 toggles it too. */
MEPUBLIC void MEAPI RRenderToggleUserHelp(RRender *rc);

ME_EXTERN_C_END

/* The guide calls RRun as RRun(rc, tick, 0) and as RRun(rc, tick), and
 * writes ticks both with and without a user-data parameter. All four
 * combinations work: in C11 RRun is also a macro that counts its arguments
 * and picks RRunNoData for a one-parameter tick (_Generic); in C++ there
 * are overloads (there, pass a real tick: a null one is ambiguous). */
#if !defined(__cplusplus) && defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#  define R_RUN_PICK_(tick) _Generic((tick), RMainLoopCallBackNoData : RRunNoData, default : RRun)
#  define R_RUN_3_(rc, tick, userdata) R_RUN_PICK_(tick)(rc, tick, userdata)
#  define R_RUN_2_(rc, tick) R_RUN_PICK_(tick)(rc, tick, 0)
#  define R_RUN_SELECT_(a, b, c, name, ...) name
#  define RRun(...) R_RUN_SELECT_(__VA_ARGS__, R_RUN_3_, R_RUN_2_, R_RUN_NEEDS_2_OR_3_ARGUMENTS)(__VA_ARGS__)
#elif defined(__cplusplus)
inline void RRun(RRender *rc, RMainLoopCallBack tick) { RRun(rc, tick, 0); }
inline void RRun(RRender *rc, RMainLoopCallBackNoData tick, void *userdata = 0) { RRunNoData(rc, tick, userdata); }
#endif

/* Colours given as MeReal arrays in a double build (see the header). */
#include "MeViewerColor.h"

#endif /* KARMA_MEVIEWER_H */
