/* MeViewerTypes.h: the data structures of MeViewer (Appendix B of the guide).
 *
 * Everything here is plain C so that the guide's programs can reach into the
 * structures the way it shows (rc->m_AppName, rc->m_PointLight, an
 * RObjectHeader's m_nTextureID, an RObjectVertex's m_X ...).
 *
 * Geometry (the guide's "Geometry Data Format"): an object is one
 * RObjectHeader immediately followed in memory by m_nMaxNumVertices
 * RObjectVertex records, of which the first m_nNumVertices (a multiple of 3)
 * form a triangle list. Vertex edits show in the next frame.
 *
 * Coordinates: 3D objects use the world frame of the simulation (y up). A
 * transform pointer (m_pLWMatrix) is a Karma TM (rows 0-2 the rotated axes,
 * row 3 the position, points map as p * R + t); NULL means identity. The 2D
 * list uses a virtual screen of R_2D_WIDTH x R_2D_HEIGHT units, x to the
 * right and y down from the top-left corner, stretched to the output size. */
#ifndef KARMA_MEVIEWERTYPES_H
#define KARMA_MEVIEWERTYPES_H

#include "MeGlobals.h"

ME_EXTERN_C_BEGIN

/* The guide writes the viewer's scalars as AcmeReal; they are MeReal. */
typedef MeReal AcmeReal;
typedef MeVector3 AcmeVector3;
typedef MeVector4 AcmeVector4;

#define R_2D_WIDTH 640
#define R_2D_HEIGHT 480
/* Texture slots an application may fill (the guide's limit). */
#define R_MAX_TEXTURES 25
/* Text: width and height of one character in 2D units. */
#define R_TEXT_CHAR_WIDTH 7
#define R_TEXT_CHAR_HEIGHT 14

typedef struct RObjectVertex {
  float m_X, m_Y, m_Z;    /* position in the object's frame */
  float m_NX, m_NY, m_NZ; /* unit normal */
  float m_U, m_V;         /* texture coordinates in [0, 1] */
} RObjectVertex;

typedef struct RObjectHeader {
  MeMatrix4 m_Matrix;      /* copied from m_pLWMatrix each frame (identity if none) */
  int m_nNumVertices;      /* vertices in use, a multiple of 3 */
  int m_nTextureID;        /* -1: untextured */
  int m_bIsWireFrame;      /* non-zero: draw the triangle edges only */
  float m_ColorAmbient[4]; /* RGBA */
  float m_ColorDiffuse[4];
  float m_ColorEmissive[4];
  float m_ColorSpecular[4];
  float m_SpecularPower; /* shininess, 0..128 */
} RObjectHeader;

typedef struct RGraphic {
  RObjectHeader *m_pObject;   /* the header; the vertices follow it */
  RObjectVertex *m_pVertices; /* == (RObjectVertex *)(m_pObject + 1), aligned */
  MeMatrix4Ptr m_pLWMatrix;   /* local-to-world transform, or NULL */
  int m_nMaxNumVertices;      /* vertices allocated after the header */
  struct RGraphic *m_pNext;   /* next in its render list */
  void *m_pUserData;          /* for the application */
} RGraphic;

/* A line drawn by the graphics library itself (GL_LINES), unlit. */
typedef struct RNativeLine {
  AcmeReal m_Start[3];
  AcmeReal m_End[3];
  float m_Color[4];
  const MeVector4 *m_pMatrix; /* transform of the end points, or NULL */
  struct RNativeLine *m_pNext;
} RNativeLine;

typedef struct RDirectLight {
  int m_bUseLight; /* non-zero: the light is on */
  float m_rgbAmbient[3];
  float m_rgbDiffuse[3];
  float m_rgbSpecular[3];
  float m_Direction[3]; /* the direction the light travels (need not be unit) */
} RDirectLight;

/* Intensity falls with distance d as 1 / (constant + linear d + quadratic d^2). */
typedef struct RPointLight {
  int m_bUseLight;
  float m_rgbAmbient[3];
  float m_rgbDiffuse[3];
  float m_rgbSpecular[3];
  float m_Position[3]; /* world coordinates */
  float m_AttenuationConstant;
  float m_AttenuationLinear;
  float m_AttenuationQuadratic;
} RPointLight;

/* The four lights of a render context (RLightSwitchOn / RLightSwitchOff). */
typedef enum RRenderLight { kRAmbient = 0, kRDirect1 = 1, kRDirect2 = 2, kRPoint = 3 } RRenderLight;

struct RRender;
struct RRenderPrivate;

/* The per-frame callback of RRun. The guide also writes a tick without
 * user data (`void MEAPI Tick(RRender *rc)`); MeViewer.h accepts both. */
typedef void(MEAPI *RMainLoopCallBack)(struct RRender *rc, void *userdata);
typedef void(MEAPI *RMainLoopCallBackNoData)(struct RRender *rc);

/* Controls (the guide's "Controls"): a button callback runs once when its
 * key is pressed; the mouse callback gets the pointer position in pixels
 * of the frame (x right, y down) and the buttons held (bit 0 left, bit 1
 * middle, bit 2 right). */
typedef void(MEAPI *RButtonPressCallBack)(struct RRender *rc, void *userdata);
typedef void(MEAPI *RMouseCallBack)(struct RRender *rc, int x, int y, int buttons, void *userdata);

/* Actions 0..R_MAX_ACTIONS-1 (the guide uses 1..5 in help text). */
#define R_MAX_ACTIONS 6

/* Menus (the guide's "Menu System"); the structure is private. */
typedef struct RMenu RMenu;
typedef void(MEAPI *RMenuToggleCallback)(MeBool on);
typedef void(MEAPI *RMenuValueCallback)(MeReal value);

/* The performance bar (RPerformanceBarCreate); private. */
typedef struct RPerformanceBar RPerformanceBar;

#define R_APPNAME_SIZE 256

/* The render context. Members below are the ones the guide names; change the
 * camera through the RCamera functions (or call RCameraUpdate after writing
 * the camera members directly). */
typedef struct RRender {
  /* The application's name for $APPNAME. Points at m_AppNameBuffer at
     * creation, so both strcpy(rc->m_AppName, ...) (up to R_APPNAME_SIZE-1
     * characters) and rc->m_AppName = "..." work. */
  char *m_AppName;
  char m_AppNameBuffer[R_APPNAME_SIZE];

  /* Render lists (RGraphicAddToList). */
  RGraphic *m_pRG_First;   /* 3D */
  RGraphic *m_pRG_First2D; /* 2D overlay */
  RNativeLine *m_pNL_First;

  /* Camera, spherical about the look-at point: dist >= 0.01,
     * theta in [-pi, pi] about y from the +z axis (anticlockwise seen from
     * above), phi in [-pi/2, pi/2] above the xz plane. */
  AcmeReal m_CameraLookAt[3];
  AcmeReal m_CameraDist;
  AcmeReal m_CameraTheta;
  AcmeReal m_CameraPhi;
  AcmeReal m_CameraPos[3];  /* derived by RCameraUpdate */
  AcmeReal m_CameraUp[3];   /* derived: unit, perpendicular to the view */
  MeMatrix4 m_CameraMatrix; /* derived: world to camera TM (camera looks down -z) */
  AcmeReal m_CameraFOV;     /* vertical field of view, radians */

  /* Lighting (the guide's "Lighting"): changes to the ambient colour take
     * effect next frame; after changing a light structure once RRun runs,
     * set its m_bForce...Update flag (the renderer clears it). */
  float m_rgbAmbientLightColor[3];
  int m_bUseAmbientLight;
  RDirectLight m_DirectLight1;
  RDirectLight m_DirectLight2;
  RPointLight m_PointLight;
  int m_bForceDirectLight1Update;
  int m_bForceDirectLight2Update;
  int m_bForcePointLightUpdate;

  float m_BackgroundColour[3];

  /* Output size in pixels (-size WxH) and frames drawn so far. */
  int m_nWidth;
  int m_nHeight;
  int m_nFrame;

  struct RRenderPrivate *m_pPrivate; /* the implementation's state */
} RRender;

ME_EXTERN_C_END

#endif /* KARMA_MEVIEWERTYPES_H */
