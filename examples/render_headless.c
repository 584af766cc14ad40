// Renders a model to a PNG file with no display at all: an OpenGL context from EGL (Mesa's
// surfaceless platform, or the default display) or from OSMesa, rujoco's offscreen buffer, one
// frame after a short simulation. The C equivalent of MUJOCO_GL=egl / MUJOCO_GL=osmesa.
//
// The GL platform is chosen when building, as MUJOCO_GL chooses it in Python: a process must
// load only one of libEGL and libOSMesa, since the library takes GL from the one it finds.
//
// Build:  gcc render_headless.c -I include -L target/release -lmujoco -lEGL -lm -o render_egl
//         gcc render_headless.c -DOSMESA -I include -L target/release -lmujoco -lOSMesa -lm \
//             -o render_osmesa
// Run:    LD_LIBRARY_PATH=target/release ./render_egl [model.xml] [out.png] [steps]

#ifdef OSMESA
#include <GL/osmesa.h>
#else
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

// ---- a PNG writer: stored (uncompressed) deflate blocks, CRC-32 and Adler-32 ----

static uint32_t crc_table[256];

static uint32_t crc32_of(uint32_t crc, const unsigned char* p, size_t n) {
  if (!crc_table[1]) {
    for (uint32_t i = 0; i < 256; i++) {
      uint32_t c = i;
      for (int k = 0; k < 8; k++) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      crc_table[i] = c;
    }
  }
  crc = ~crc;
  for (size_t i = 0; i < n; i++) crc = crc_table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

static void put32(unsigned char* p, uint32_t v) {
  p[0] = v >> 24; p[1] = v >> 16; p[2] = v >> 8; p[3] = v;
}

static void chunk(FILE* f, const char* type, const unsigned char* data, uint32_t n) {
  unsigned char head[8];
  put32(head, n);
  memcpy(head + 4, type, 4);
  fwrite(head, 1, 8, f);
  if (n) fwrite(data, 1, n, f);
  uint32_t crc = crc32_of(crc32_of(0, (const unsigned char*)type, 4), data, n);
  unsigned char tail[4];
  put32(tail, crc);
  fwrite(tail, 1, 4, f);
}

// rgb: width*height*3 bytes, bottom row first (as glReadPixels gives it)
static int write_png(const char* path, const unsigned char* rgb, int width, int height) {
  size_t row = 1 + 3 * (size_t)width, raw_n = row * height;
  unsigned char* raw = malloc(raw_n);
  for (int y = 0; y < height; y++) {
    raw[y * row] = 0;  // filter: none
    memcpy(raw + y * row + 1, rgb + (size_t)(height - 1 - y) * 3 * width, 3 * (size_t)width);
  }
  size_t blocks = (raw_n + 65534) / 65535;
  size_t z_n = 2 + raw_n + 5 * blocks + 4;
  unsigned char* z = malloc(z_n);
  unsigned char* p = z;
  *p++ = 0x78; *p++ = 0x01;
  uint32_t a = 1, b = 0;
  for (size_t i = 0; i < raw_n; i++) { a = (a + raw[i]) % 65521; b = (b + a) % 65521; }
  for (size_t off = 0; off < raw_n; off += 65535) {
    size_t n = raw_n - off < 65535 ? raw_n - off : 65535;
    *p++ = off + n == raw_n;
    *p++ = n & 0xFF; *p++ = n >> 8; *p++ = ~n & 0xFF; *p++ = (~n >> 8) & 0xFF;
    memcpy(p, raw + off, n);
    p += n;
  }
  put32(p, (b << 16) | a);
  FILE* f = fopen(path, "wb");
  if (!f) { free(raw); free(z); return 0; }
  fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
  unsigned char ihdr[13];
  put32(ihdr, width); put32(ihdr + 4, height);
  ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = 0; ihdr[11] = 0; ihdr[12] = 0;
  chunk(f, "IHDR", ihdr, 13);
  chunk(f, "IDAT", z, (uint32_t)z_n);
  chunk(f, "IEND", NULL, 0);
  fclose(f);
  free(raw); free(z);
  return 1;
}

// ---- GL contexts without a display ----

#ifndef OSMESA
static const char* backend = "EGL";

static int gl_context(void) {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
      (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  if (get_platform_display) {
    dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  }
  if (dpy == EGL_NO_DISPLAY) dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) return 0;
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                            EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
                            EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, attribs, &config, 1, &n) || n < 1) return 0;
  if (!eglBindAPI(EGL_OPENGL_API)) return 0;
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (ctx == EGL_NO_CONTEXT) return 0;
  return eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx);
}

#else
static const char* backend = "OSMesa";
static unsigned char osmesa_buffer[4 * 64 * 64];

static int gl_context(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, NULL);
  // the window buffer is unused: rendering goes to the offscreen framebuffer
  return ctx && OSMesaMakeCurrent(ctx, osmesa_buffer, GL_UNSIGNED_BYTE, 64, 64);
}
#endif

int main(int argc, char** argv) {
  int a = 1;
  const char* path = a < argc ? argv[a++] : "models/arm3.xml";
  const char* out = a < argc ? argv[a++] : "frame.png";
  int steps = a < argc ? atoi(argv[a++]) : 500;

  if (!gl_context()) {
    fprintf(stderr, "OpenGL context creation failed (%s): install Mesa's %s\n", backend,
            backend[0] == 'E' ? "libegl1 and libgl1-mesa-dri" : "libosmesa6");
    return 1;
  }

  char error[1000] = "";
  mjModel* m = mj_loadXML(path, NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "cannot load %s: %s\n", path, error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  for (int i = 0; i < steps; i++) mj_step(m, d);

  mjvCamera cam;
  mjvOption opt;
  mjvScene scn;
  mjrContext con;
  mjv_defaultCamera(&cam);
  mjv_defaultFreeCamera(m, &cam);
  mjv_defaultOption(&opt);
  mjv_defaultScene(&scn);
  mjr_defaultContext(&con);
  mjv_makeScene(m, &scn, 2000);
  mjr_makeContext(m, &con, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_OFFSCREEN, &con);

  mjrRect viewport = mjr_maxViewport(&con);
  int w = viewport.width, h = viewport.height;
  mjv_updateScene(m, d, &opt, NULL, &cam, mjCAT_ALL, &scn);
  mjr_render(viewport, &scn, &con);
  char stamp[64];
  snprintf(stamp, sizeof(stamp), "t = %.3f s", d->time);
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, stamp, NULL, &con);

  unsigned char* rgb = malloc(3 * (size_t)w * h);
  mjr_readPixels(rgb, NULL, viewport, &con);
  int written = write_png(out, rgb, w, h);
  printf("%s: %dx%d frame at t = %.3f s through %s -> %s\n", path, w, h, d->time, backend,
         written ? out : "(write failed)");

  free(rgb);
  mjr_freeContext(&con);
  mjv_freeScene(&scn);
  mj_deleteData(d);
  mj_deleteModel(m);
  return written ? 0 : 1;
}
