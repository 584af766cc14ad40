// Misuse of the OpenGL layer (mjr_, mjui_update, mjui_render), printed for comparison against
// 2.2.2: calls with no current OpenGL context, contexts too old, contexts made or freed twice,
// sizes over the implementation's limits, bad indices, NULL and empty buffers. Each case runs
// in a forked child, so a crash of the library shows as "signal N" and the next case runs.
// The error handler prints the message and jumps back to the case's end; the warning handler
// prints. A case marked "[ub]" does something 2.2.2 leaves undefined (it reads out of bounds).
//   render_misuse [CASE]     (CASE: run only the case of this name)
// Built with -DNO_PLATFORM (without -lOSMesa) it runs only the cases that need no OpenGL
// platform library in the process.
#ifndef NO_PLATFORM
#include <GL/osmesa.h>
#endif
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <mujoco/mujoco.h>

#define W 200
#define H 150

static jmp_buf jump;
static int armed = 0;
static mjrContext con;
static mjModel* model = NULL;

static void on_error(const char* msg) {
  printf("  error: %s\n", msg);
  fflush(stdout);
  if (armed) {
    armed = 0;
    longjmp(jump, 1);
  }
  _exit(2);
}

static void on_warning(const char* msg) {
  printf("  warning: %s\n", msg);
  fflush(stdout);
}

static mjrRect rect(int l, int b, int w, int h) {
  mjrRect r = {l, b, w, h};
  return r;
}

__attribute__((unused)) static unsigned long long fnv(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

//---------------------------------------- models ---------------------------------------------------

static const char* XML_FULL =
    "<mujoco><asset>"
    "<texture name='sky' type='skybox' builtin='gradient' width='32' height='32'/>"
    "<texture name='grid' type='2d' builtin='checker' width='64' height='64'/>"
    "<material name='grid' texture='grid' texrepeat='4 4'/>"
    "<mesh name='tet' vertex='0 0 0 1 0 0 0 1 0 0 0 1'/>"
    "<hfield name='hf' nrow='3' ncol='3' size='1 1 0.2 0.1'/>"
    "</asset><worldbody><light pos='0 0 3'/>"
    "<geom type='plane' size='2 2 .1' material='grid'/>"
    "<geom type='hfield' hfield='hf' pos='3 0 0'/>"
    "<body pos='0 0 1'><freejoint/><geom type='mesh' mesh='tet' material='grid'/>"
    "<geom type='box' size='.1 .1 .1' pos='.5 0 0'/></body>"
    "</worldbody></mujoco>";
__attribute__((unused)) static const char* XML_EMPTY = "<mujoco/>";
#ifndef NO_PLATFORM
static const char* XML_BIGTEX =
    "<mujoco><asset><texture name='t' type='2d' builtin='checker' width='40000' height='2'/>"
    "<material name='m' texture='t'/></asset>"
    "<worldbody><geom size='1' material='m'/></worldbody></mujoco>";
static const char* XML_OFFBIG =
    "<mujoco><visual><global offwidth='100000' offheight='100'/></visual></mujoco>";
static const char* XML_OFFNEG =
    "<mujoco><visual><global offwidth='0' offheight='100'/></visual></mujoco>";
static const char* XML_SAMPLES =
    "<mujoco><visual><quality offsamples='64'/></visual></mujoco>";
static const char* XML_SHADOW =
    "<mujoco><visual><quality shadowsize='100000'/></visual></mujoco>";

#endif

static mjModel* load(const char* xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "m.xml", (int)strlen(xml));
  memcpy(vfs.filedata[0], xml, strlen(xml));
  char err[500] = "";
  mjModel* m = mj_loadXML("m.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  if (!m) {
    printf("  load error: %s\n", err);
    fflush(stdout);
    _exit(3);
  }
  return m;
}

//---------------------------------------- OpenGL ---------------------------------------------------

#ifndef NO_PLATFORM
static unsigned char window[4 * W * H];
static OSMesaContext osmesa = NULL;

// a current OSMesa context of W x H (its window framebuffer); major > 0 asks for that version
static void make_current(int major) {
  if (major > 0) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_STENCIL_BITS, 8, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, major,
                           OSMESA_CONTEXT_MINOR_VERSION, 0, 0};
    osmesa = OSMesaCreateContextAttribs(attribs, NULL);
  } else {
    osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  }
  if (!osmesa || !OSMesaMakeCurrent(osmesa, window, 0x1401 /* GL_UNSIGNED_BYTE */, W, H)) {
    printf("  no OSMesa context\n");
    fflush(stdout);
    _exit(3);
  }
}

static void release_current(void) {
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
}
#endif

// the context's state after a case
static void print_context(void) {
  printf("  con: gl %d window %d cur %d off %d %d %d fbo %u %u shadow %d %u font %d %d %u"
         " ntex %d tex0 %u planes %d meshes %d hfields %d builtin %d nskin %d\n",
         con.glInitialized, con.windowAvailable, con.currentBuffer, con.offWidth,
         con.offHeight, con.offSamples, con.offFBO, con.offFBO_r, con.shadowSize,
         con.shadowFBO, con.fontScale, con.rangeFont, con.baseFontNormal, con.ntexture,
         con.texture[0], con.rangePlane, con.rangeMesh, con.rangeHField, con.rangeBuiltin,
         con.nskin);
  for (int i = 0; i < mjNAUX; i++) {
    if (con.auxFBO[i] || con.auxWidth[i]) {
      printf("  aux %d: %d x %d samples %d fbo %u %u\n", i, con.auxWidth[i], con.auxHeight[i],
             con.auxSamples[i], con.auxFBO[i], con.auxFBO_r[i]);
    }
  }
}

static void print_glerror(void) {
  printf("  glerror 0x%x\n", mjr_getError());
}

//---------------------------------------- cases: no context ----------------------------------------

// every entry point with no OpenGL context ever made current (a cleared mjrContext)
static void nc_makeContext(void) { mjr_makeContext(model, &con, 100); }
static void nc_makeContext_nomodel(void) { mjr_makeContext(NULL, &con, 150); }
static void nc_freeContext(void) { mjr_freeContext(&con); print_context(); }
// a scene of the full model, updated (or only made: no cameras)
static mjvScene* scene(int update) {
  static mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(model, &scn, 1000);
  if (update) {
    mjData* d = mj_makeData(model);
    mj_forward(model, d);
    mjvOption opt;
    mjv_defaultOption(&opt);
    mjvCamera cam;
    mjv_defaultCamera(&cam);
    mjvPerturb pert;
    mjv_defaultPerturb(&pert);
    mjv_updateScene(model, d, &opt, &pert, &cam, mjCAT_ALL, &scn);
  }
  return &scn;
}
static void nc_render(void) { mjr_render(rect(0, 0, W, H), scene(1), &con); }
static void nc_render_nocamera(void) { mjr_render(rect(0, 0, W, H), scene(0), &con); }
static void nc_text(void) { mjr_text(mjFONT_NORMAL, "text", &con, 0.1f, 0.1f, 1, 1, 1); }
static void nc_overlay(void) {
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, rect(0, 0, W, H), "a", "b", &con);
}
static void nc_overlay_empty(void) {
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, rect(0, 0, 0, H), "a", "b", &con);
}
static void nc_figure(void) {
  mjvFigure* fig = malloc(sizeof(mjvFigure));
  mjv_defaultFigure(fig);
  mjr_figure(rect(0, 0, W, H), fig, &con);
  free(fig);
}
static void nc_rectangle(void) { mjr_rectangle(rect(0, 0, W, H), 1, 0, 0, 1); }
static void nc_rectangle_empty(void) { mjr_rectangle(rect(0, 0, W, -1), 1, 0, 0, 1); }
static void nc_label(void) {
  mjr_label(rect(0, 0, W, H), mjFONT_NORMAL, "x", 1, 1, 1, 1, 0, 0, 0, &con);
}
static void nc_readPixels(void) {
  unsigned char rgb[3 * 4];
  mjr_readPixels(rgb, NULL, rect(0, 0, 2, 2), &con);
}
static void nc_readPixels_null(void) { mjr_readPixels(NULL, NULL, rect(0, 0, 2, 2), &con); }
static void nc_drawPixels(void) {
  unsigned char rgb[3 * 4] = {0};
  mjr_drawPixels(rgb, NULL, rect(0, 0, 2, 2), &con);
}
static void nc_blitBuffer(void) {
  mjr_blitBuffer(rect(0, 0, 2, 2), rect(0, 0, 2, 2), 1, 1, &con);
}
static void nc_setBuffer(void) { mjr_setBuffer(mjFB_OFFSCREEN, &con); }
static void nc_restoreBuffer(void) { mjr_restoreBuffer(&con); }
static void nc_setAux(void) { mjr_setAux(0, &con); }
static void nc_setAux_bad(void) { mjr_setAux(-1, &con); }
static void nc_blitAux(void) { mjr_blitAux(0, rect(0, 0, 2, 2), 0, 0, &con); }
static void nc_addAux(void) { mjr_addAux(0, 100, 100, 0, &con); }
static void nc_addAux_empty(void) { mjr_addAux(0, 0, 0, 0, &con); print_context(); }
static void nc_addAux_bad(void) { mjr_addAux(mjNAUX, 100, 100, 0, &con); }
static void nc_uploadTexture(void) { mjr_uploadTexture(model, &con, 0); }
static void nc_uploadMesh(void) { mjr_uploadMesh(model, &con, 0); }
static void nc_uploadMesh_bad(void) { mjr_uploadMesh(model, &con, 5); }
static void nc_uploadHField(void) { mjr_uploadHField(model, &con, 0); }
static void nc_changeFont(void) { mjr_changeFont(200, &con); }
static void nc_changeFont_bad(void) { mjr_changeFont(123, &con); }
static void nc_getError(void) { print_glerror(); }
static void nc_finish(void) { mjr_finish(); }
static void nc_maxViewport(void) {
  mjrRect r = mjr_maxViewport(&con);
  printf("  viewport %d %d %d %d\n", r.left, r.bottom, r.width, r.height);
}
static void nc_maxViewport_off(void) {
  con.currentBuffer = mjFB_OFFSCREEN;
  con.offWidth = 64;
  con.offHeight = 48;
  nc_maxViewport();
}
static void nc_findRect(void) {
  mjrRect r[2] = {{0, 0, 10, 10}, {10, 0, 10, 10}};
  printf("  findRect %d %d\n", mjr_findRect(15, 5, 2, r), mjr_findRect(50, 5, 2, r));
}
static mjUI ui;
static mjuiState uistate;
static void make_ui(void) {
  memset(&ui, 0, sizeof(ui));
  memset(&uistate, 0, sizeof(uistate));
  ui.spacing = mjui_themeSpacing(0);
  ui.color = mjui_themeColor(0);
  ui.rectid = 1;
  ui.auxid = 0;
  ui.radiocol = 0;
  static int check = 0;
  mjuiDef defs[] = {{mjITEM_SECTION, "Section", 1, NULL, ""},
                    {mjITEM_CHECKINT, "Check", 2, &check, ""},
                    {mjITEM_END}};
  mjui_add(&ui, defs);
  uistate.nrect = 2;
  uistate.rect[1] = rect(0, 0, 150, 150);
}
static void nc_ui_update(void) {
  make_ui();
  mjui_resize(&ui, &con);
  mjui_update(-1, -1, &ui, &uistate, &con);
}
static void nc_ui_render(void) {
  make_ui();
  mjui_render(&ui, &uistate, &con);
}

//---------------------------------------- cases: OpenGL versions -----------------------------------

#ifndef NO_PLATFORM
// an OpenGL context made current only after a first mjr_makeContext without one
static void late_context(void) {
  jmp_buf outer;
  memcpy(outer, jump, sizeof(jmp_buf));
  if (!setjmp(jump)) {
    armed = 1;
    mjr_makeContext(model, &con, 100);
  }
  memcpy(jump, outer, sizeof(jmp_buf));
  armed = 1;
  make_current(0);
  mjr_makeContext(model, &con, 100);
  print_context();
}

// a context of the version Mesa's overrides give (env vars set by the test), or of major 1
static void version_context(void) {
  make_current(0);
  mjr_makeContext(model, &con, 100);
  print_context();
}
static void version_override(const char* var, const char* value) {
  setenv(var, value, 1);
  version_context();
}
static void version_1_4(void) { version_override("MESA_GL_VERSION_OVERRIDE", "1.4"); }
static void version_1_5(void) { version_override("MESA_GL_VERSION_OVERRIDE", "1.5"); }
static void no_framebuffer_object(void) {
  version_override("MESA_EXTENSION_OVERRIDE", "-GL_ARB_framebuffer_object");
}
static void no_vertex_buffer_object(void) {
  version_override("MESA_EXTENSION_OVERRIDE", "-GL_ARB_vertex_buffer_object");
}
static void version_1(void) {
  make_current(1);
  mjr_makeContext(model, &con, 100);
  print_context();
}

//---------------------------------------- cases: made contexts -------------------------------------

static void made(void) {
  make_current(0);
  mjr_makeContext(model, &con, 100);
}

static void make_twice(void) {
  made();
  print_context();
  mjr_makeContext(model, &con, 200);
  print_context();
  print_glerror();
}
static void make_other_model(void) {
  made();
  mjModel* m2 = load(XML_EMPTY);
  mjr_makeContext(m2, &con, 150);
  print_context();
  mjr_makeContext(NULL, &con, 150);
  print_context();
  print_glerror();
}
static void free_twice(void) {
  made();
  mjr_freeContext(&con);
  print_context();
  mjr_freeContext(&con);
  print_context();
  print_glerror();
}
static void free_default(void) {
  make_current(0);
  mjr_freeContext(&con);
  print_context();
  mjr_makeContext(model, &con, 100);
  mjr_freeContext(&con);
  mjr_defaultContext(&con);
  mjr_freeContext(&con);
  print_context();
  print_glerror();
}
static void make_after_free(void) {
  made();
  mjr_freeContext(&con);
  mjr_makeContext(model, &con, 300);
  print_context();
  print_glerror();
}
static void released(void) {
  made();
  release_current();
  mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(model, &scn, 100);
  mjr_render(rect(0, 0, W, H), &scn, &con);
  mjr_text(mjFONT_NORMAL, "text", &con, 0.1f, 0.1f, 1, 1, 1);
  mjr_finish();
  print_glerror();
  print_context();
}

static void with_model(const char* xml, int fontscale) {
  make_current(0);
  mjModel* m = load(xml);
  mjr_makeContext(m, &con, fontscale);
  print_context();
  print_glerror();
}
static void big_texture(void) { with_model(XML_BIGTEX, 100); }
static void big_offscreen(void) { with_model(XML_OFFBIG, 100); }
static void zero_offscreen(void) { with_model(XML_OFFNEG, 100); }
static void many_samples(void) { with_model(XML_SAMPLES, 100); }
static void big_shadow(void) { with_model(XML_SHADOW, 100); }
static void fontscale_123(void) { with_model(XML_EMPTY, 123); }
static void fontscale_0(void) { with_model(XML_EMPTY, 0); }
static void fontscale_1000(void) { with_model(XML_EMPTY, 1000); }
static void fontscale_negative(void) { with_model(XML_EMPTY, -500); }

static void change_font(int scale) {
  made();
  mjr_changeFont(scale, &con);
  print_context();
  print_glerror();
}
static void changeFont_123(void) { change_font(123); }
static void changeFont_0(void) { change_font(0); }
static void changeFont_1000(void) { change_font(1000); }
static void changeFont_250(void) { change_font(250); }

static void upload_texture_big(void) {
  made();
  // texture 1 enlarged past the implementation's limit, same data
  mjModel* m = mj_copyModel(NULL, model);
  m->tex_width[1] = 40000;
  m->tex_height[1] = 1;
  mjr_uploadTexture(m, &con, 1);
  print_glerror();
}
static void upload_texture_short(void) {
  made();
  // texture 1 enlarged within the limit, past the model's texture data
  mjModel* m = mj_copyModel(NULL, model);
  m->tex_width[1] = 4000;
  m->tex_height[1] = 4000;
  mjr_uploadTexture(m, &con, 1);
  print_glerror();
}
static void upload_bad(int which, int id) {
  made();
  if (which == 0) mjr_uploadTexture(model, &con, id);
  if (which == 1) mjr_uploadMesh(model, &con, id);
  if (which == 2) mjr_uploadHField(model, &con, id);
  print_glerror();
}
static void uploadTexture_huge(void) { upload_bad(0, 1 << 28); }
static void uploadTexture_negative(void) { upload_bad(0, -1); }
static void uploadMesh_negative(void) { upload_bad(1, -1); }
static void uploadMesh_past(void) { upload_bad(1, 1); }
static void uploadHField_negative(void) { upload_bad(2, -1); }
static void uploadHField_past(void) { upload_bad(2, 1); }
static void upload_null_model(void) {
  made();
  mjr_uploadMesh(NULL, &con, 0);
}

static void aux(int index, int w, int h, int samples) {
  made();
  mjr_addAux(index, w, h, samples, &con);
  print_context();
  print_glerror();
}
static void addAux_negative(void) { aux(-1, 100, 100, 0); }
static void addAux_past(void) { aux(mjNAUX, 100, 100, 0); }
static void addAux_huge(void) { aux(1, 100000, 100, 0); }
static void addAux_zero(void) { aux(1, 0, 100, 0); }
static void addAux_samples(void) { aux(2, 64, 48, 1000); }
static void addAux_twice(void) {
  made();
  mjr_addAux(3, 64, 48, 4, &con);
  mjr_addAux(3, 32, 24, 0, &con);
  print_context();
  mjr_addAux(3, -1, 24, 0, &con);
  print_context();
  print_glerror();
}
static void setAux_negative(void) { made(); mjr_setAux(-1, &con); }
static void setAux_past(void) { made(); mjr_setAux(mjNAUX, &con); }
static void setAux_missing(void) { made(); mjr_setAux(4, &con); }
static void blitAux_negative(void) { made(); mjr_blitAux(-3, rect(0, 0, 2, 2), 0, 0, &con); }
static void blitAux_missing(void) {
  made();
  mjr_blitAux(4, rect(0, 0, 2, 2), 0, 0, &con);
  print_glerror();
}
static void setBuffer_invalid(void) {
  made();
  mjr_setBuffer(7, &con);
  print_context();
  mjr_restoreBuffer(&con);
  mjr_setBuffer(-1, &con);
  print_context();
  print_glerror();
}
static void setBuffer_nobuffer(void) {
  make_current(0);
  mjModel* m = load(XML_OFFNEG);
  mjr_makeContext(m, &con, 100);
  con.windowAvailable = 0;
  mjr_setBuffer(mjFB_WINDOW, &con);
}
static void pixels(void) {
  made();
  unsigned char rgb[3 * W * H];
  float depth[W * H];
  mjr_readPixels(NULL, NULL, rect(0, 0, W, H), &con);
  print_glerror();
  mjr_readPixels(rgb, depth, rect(0, 0, 0, 0), &con);
  print_glerror();
  mjr_readPixels(rgb, NULL, rect(0, 0, -5, 10), &con);
  print_glerror();
  mjr_readPixels(NULL, depth, rect(0, 0, 10, -5), &con);
  print_glerror();
  mjr_drawPixels(NULL, NULL, rect(0, 0, W, H), &con);
  print_glerror();
  mjr_drawPixels(rgb, depth, rect(0, 0, 0, 0), &con);
  print_glerror();
  mjr_drawPixels(rgb, NULL, rect(0, 0, -5, 10), &con);
  print_glerror();
  mjr_drawPixels(NULL, depth, rect(5, 5, 10, -5), &con);
  print_glerror();
  mjr_setBuffer(mjFB_OFFSCREEN, &con);
  mjr_readPixels(rgb, NULL, rect(0, 0, -5, 10), &con);
  print_glerror();
  mjr_blitBuffer(rect(0, 0, -5, 10), rect(0, 0, 10, 10), 1, 1, &con);
  print_glerror();
}

static void render_null_scene(void) {
  made();
  mjr_render(rect(0, 0, W, H), NULL, &con);
}
static void render_null_context(void) {
  made();
  mjr_render(rect(0, 0, W, H), scene(1), NULL);
}
static void render_null_context_nocamera(void) {
  made();
  mjr_render(rect(0, 0, W, H), scene(0), NULL);
  mjr_render(rect(0, 0, 0, H), scene(1), NULL);
}
static void render_empty_viewport(void) {
  made();
  mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(model, &scn, 100);
  mjr_render(rect(0, 0, 0, 0), &scn, &con);
  mjr_render(rect(0, 0, -10, H), &scn, &con);
  print_glerror();
}

// a scene of the full model rendered with the context of an empty model
static void render_other_model(void) {
  make_current(0);
  mjModel* m2 = load(XML_EMPTY);
  mjr_makeContext(m2, &con, 100);
  mjvScene* scn = scene(1);
  mjr_setBuffer(mjFB_WINDOW, &con);
  mjr_render(rect(0, 0, W, H), scn, &con);
  mjr_finish();
  static unsigned char rgb[3 * W * H];
  mjr_readPixels(rgb, NULL, rect(0, 0, W, H), &con);
  printf("  ngeom %d hash %016llx\n", scn->ngeom, fnv(rgb, sizeof(rgb)));
  print_glerror();
}

static void figure(int line, int pnt) {
  made();
  mjvFigure* fig = calloc(1, sizeof(mjvFigure));
  mjv_defaultFigure(fig);
  for (int i = 0; i < mjMAXLINEPNT; i++) {
    fig->linedata[line][2 * i] = (float)i;
    fig->linedata[line][2 * i + 1] = (float)(i % 7);
  }
  fig->linepnt[line] = pnt;
  mjr_figure(rect(0, 0, W, H), fig, &con);
  mjr_finish();
  static unsigned char rgb[3 * W * H];
  mjr_readPixels(rgb, NULL, rect(0, 0, W, H), &con);
  printf("  range %g %g %g %g hash %016llx\n", fig->range[0][0], fig->range[0][1],
         fig->range[1][0], fig->range[1][1], fnv(rgb, sizeof(rgb)));
  print_glerror();
  free(fig);
}
static void figure_past_line(void) { figure(0, mjMAXLINEPNT + 200); }
static void figure_huge(void) { figure(0, 1 << 28); }
static void figure_past_struct(void) { figure(mjMAXLINE - 1, 3 * mjMAXLINEPNT); }
static void figure_null(void) { made(); mjr_figure(rect(0, 0, W, H), NULL, &con); }
static void figure_null_empty(void) { made(); mjr_figure(rect(0, 0, 0, H), NULL, &con); }
#endif

//---------------------------------------- driver ---------------------------------------------------

typedef struct {
  const char* name;
  void (*run)(void);
  int ub;  // undefined in 2.2.2
} Case;

#define C(f) {#f, f, 0}
#define UB(f) {#f, f, 1}

static const Case cases[] = {
    C(nc_makeContext), C(nc_makeContext_nomodel), C(nc_freeContext), C(nc_render), C(nc_render_nocamera), C(nc_text),
    C(nc_overlay), C(nc_overlay_empty), C(nc_figure), C(nc_rectangle), C(nc_rectangle_empty),
    C(nc_label), C(nc_readPixels), C(nc_readPixels_null), C(nc_drawPixels), C(nc_blitBuffer),
    C(nc_setBuffer), C(nc_restoreBuffer), C(nc_setAux), C(nc_setAux_bad), C(nc_blitAux),
    C(nc_addAux), C(nc_addAux_empty), C(nc_addAux_bad), C(nc_uploadTexture),
    C(nc_uploadMesh), C(nc_uploadMesh_bad), C(nc_uploadHField), C(nc_changeFont),
    C(nc_changeFont_bad), C(nc_getError), C(nc_finish), C(nc_maxViewport),
    C(nc_maxViewport_off), C(nc_findRect), C(nc_ui_update), C(nc_ui_render),
#ifndef NO_PLATFORM
    C(late_context), C(version_context), C(version_1_4), C(version_1_5),
    C(no_framebuffer_object), C(no_vertex_buffer_object), C(version_1), C(make_twice), C(make_other_model),
    C(free_twice), C(free_default), C(make_after_free), C(released), C(big_texture),
    C(big_offscreen), C(zero_offscreen), C(many_samples), C(big_shadow),
    C(fontscale_123), C(fontscale_0), C(fontscale_1000), C(fontscale_negative),
    C(changeFont_123), C(changeFont_0), C(changeFont_1000), C(changeFont_250),
    C(upload_texture_big), UB(upload_texture_short), C(uploadTexture_huge), UB(uploadTexture_negative),
    C(uploadMesh_negative), C(uploadMesh_past), C(uploadHField_negative),
    C(uploadHField_past), C(upload_null_model), C(addAux_negative), C(addAux_past),
    C(addAux_huge), C(addAux_zero), C(addAux_samples), C(addAux_twice), C(setAux_negative),
    C(setAux_past), C(setAux_missing), C(blitAux_negative), C(blitAux_missing),
    C(setBuffer_invalid), C(setBuffer_nobuffer), C(pixels), C(render_null_scene),
    C(render_null_context), C(render_null_context_nocamera),
    C(render_empty_viewport), C(render_other_model),
    C(figure_past_line), C(figure_huge), UB(figure_past_struct), C(figure_null), C(figure_null_empty),
#endif
};

int main(int argc, char** argv) {
  mju_user_error = on_error;
  mju_user_warning = on_warning;
  for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
    const Case* c = cases + k;
    if (argc > 1 && strcmp(argv[1], c->name)) {
      continue;
    }
    printf("case %s%s\n", c->name, c->ub ? " [ub]" : "");
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
      model = load(XML_FULL);
      mjr_defaultContext(&con);
      if (!setjmp(jump)) {
        armed = 1;
        c->run();
        armed = 0;
        printf("  returned\n");
      } else {
        printf("  ended by error\n");
      }
      fflush(stdout);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) {
      printf("  result: signal %d\n", WTERMSIG(status));
    } else {
      printf("  result: exit %d\n", WEXITSTATUS(status));
    }
    fflush(stdout);
  }
  return 0;
}
