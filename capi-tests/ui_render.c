// The UI framework drawn and driven under OSMesa: two panels like simulate's (every item
// type), at several font scales and themes, mjui_update / mjui_render into the window, then a
// scripted sequence of mouse, wheel and key events through mjuiState filled as simulate's
// GLFW callbacks fill it. After each event: the returned items, the data, the UI's tracking
// and edit state, and a hash of the window's pixels.
//   ui_render [DUMPDIR]   (DUMPDIR: write every frame as a PPM image there)
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mujoco/mujoco.h>

#define W 1400
#define H 720
static unsigned char buffer[4 * W * H];
static unsigned char rgb[3 * W * H];
static const char* dumpdir = NULL;

static mjrContext con;
static mjUI ui0, ui1;
static mjuiState st;
static double now = 100;
static int frame = 0;
static int enable2 = 1, enable3 = 0;

// data
static int ival[12];
static mjtByte bval[4];
static mjtNum nval[16];
static char tval[mjMAXUINAME] = "qpos";
static char tval2[mjMAXUINAME] = "";

static unsigned long long fnv(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

static int predicate(int category, void* userdata) {
  (void)userdata;
  if (category == 2) return enable2;
  if (category == 3) return enable3;
  return 1;
}

static mjuiDef defs0[] = {
  {mjITEM_SECTION, "File", 1, NULL, "AF"},
  {mjITEM_BUTTON, "Save xml", 2, NULL, ""},
  {mjITEM_BUTTON, "Save mjb", 2, NULL, ""},
  {mjITEM_BUTTON, "Print model", 2, NULL, "CM"},
  {mjITEM_BUTTON, "Print data", 3, NULL, "CD"},
  {mjITEM_BUTTON, "Quit", 1, NULL, "CQ"},
  {mjITEM_SECTION, "Option", 0, NULL, "AO"},
  {mjITEM_SELECT, "Spacing", 1, ival + 0, "Tight\nWide"},
  {mjITEM_SELECT, "Color", 1, ival + 1, "Default\nOrange\nWhite\nBlack"},
  {mjITEM_CHECKINT, "Help", 2, ival + 2, " #290"},
  {mjITEM_CHECKINT, "Info", 3, ival + 3, " #291"},
  {mjITEM_CHECKBYTE, "Profiler", 2, bval + 0, " #292"},
  {mjITEM_CHECKBYTE, "Sensor", 2, bval + 1, "S#293"},
  {mjITEM_SLIDERINT, "Refresh", 2, ival + 4, "0 100"},
  {mjITEM_SLIDERINT, "Fine", 2, ival + 9, "0 10 5"},
  {mjITEM_SECTION, "Simulation", 1, NULL, "AS"},
  {mjITEM_RADIO, "", 2, ival + 5, "Pause\nRun"},
  {mjITEM_RADIO, "Modes", 2, ival + 6, "Alpha\nBeta\nGamma\nDelta\nEpsilon"},
  {mjITEM_RADIOLINE, "Line", 2, ival + 7, "X\nYY\nZZZ\nW"},
  {mjITEM_SEPARATOR, "Noise", mjSEPCLOSED + 1, NULL, ""},
  {mjITEM_SLIDERNUM, "Scale", 2, nval + 0, "0 2"},
  {mjITEM_SLIDERNUM, "Rate", 3, nval + 1, "-1 2 10"},
  {mjITEM_SEPARATOR, "Closed", mjSEPCLOSED, NULL, ""},
  {mjITEM_CHECKINT, "Hidden a", 2, ival + 10, ""},
  {mjITEM_CHECKINT, "Hidden b", 2, ival + 11, ""},
  {mjITEM_SLIDERINT, "Hidden c", 2, ival + 8, "0 10 5"},
  {mjITEM_SECTION, "Watch", 1, NULL, "AW"},
  {mjITEM_EDITTXT, "Field", 2, tval, "qpos"},
  {mjITEM_EDITTXT, "Name", 2, tval2, ""},
  {mjITEM_EDITINT, "Index", 2, ival + 8, "1"},
  {mjITEM_EDITINT, "Pair", 2, ival + 10, "2 -5 5 0 100"},
  {mjITEM_EDITNUM, "Vec", 2, nval + 2, "3 -1 1 -2 2 0 0"},
  {mjITEM_EDITNUM, "Free", 3, nval + 5, "2"},
  {mjITEM_STATIC, "Value", 2, NULL, " "},
  {mjITEM_STATIC, "Lines", 2, NULL, "one\ntwo\nthree"},
  {mjITEM_STATIC, "", 2, NULL, "unnamed"},
  {mjITEM_END}
};

static mjuiDef defs1[] = {
  {mjITEM_SECTION, "Joint", 1, NULL, "AJ"},
  {mjITEM_SEPARATOR, "Hinges", mjSEPCLOSED + 1, NULL, ""},
  {mjITEM_SLIDERNUM, "hip", 2, nval + 7, "-1 1"},
  {mjITEM_SLIDERNUM, "knee", 2, nval + 8, "-2 0.5"},
  {mjITEM_SLIDERNUM, "ankle", 3, nval + 9, "0 3"},
  {mjITEM_SECTION, "Control", 1, NULL, "AC"},
  {mjITEM_BUTTON, "Clear all", 2, NULL, ""},
  {mjITEM_SLIDERNUM, "motor0", 2, nval + 10, "-1 1"},
  {mjITEM_SLIDERNUM, "motor1", 2, nval + 11, "-1 1"},
  {mjITEM_SLIDERNUM, "motor2", 2, nval + 12, "-1 1"},
  {mjITEM_SLIDERNUM, "motor3", 2, nval + 13, "-1 1"},
  {mjITEM_SLIDERNUM, "motor4", 2, nval + 14, "-1 1"},
  {mjITEM_SLIDERNUM, "motor5", 2, nval + 15, "-1 1"},
  {mjITEM_SECTION, "Hidden title", 2, NULL, ""},
  {mjITEM_BUTTON, "Alone", 2, NULL, "S#300"},
  {mjITEM_SECTION, "Info", 1, NULL, ""},
  {mjITEM_STATIC, "Time", 2, NULL, "1.25\n0.50\n0.75\n1\n2\n3\n4\n5"},
  {mjITEM_STATIC, "Size", 2, NULL, "10\n20\n30\n40\n50\n60"},
  {mjITEM_END}
};

// ------------------------------------------------------------------ printing and frames

static void print_item(const char* who, mjuiItem* it) {
  if (it)
    printf(" %s %d/%d '%s'", who, it->sectionid, it->itemid, it->name);
  else
    printf(" %s none", who);
}

static void print_ui(const char* name, mjUI* ui) {
  printf("  %s scroll %d h %d mouse %d %d help %d edit %d %d cur %d scr %d text '%s'", name,
         ui->scroll, ui->height, ui->mousesect, ui->mouseitem, ui->mousehelp, ui->editsect,
         ui->edititem, ui->editcursor, ui->editscroll, ui->edittext);
  print_item("changed", ui->editchanged);
  printf(" sect");
  for (int s = 0; s < ui->nsect; s++) printf(" %d", ui->sect[s].state);
  printf(" seps");
  for (int s = 0; s < ui->nsect; s++)
    for (int i = 0; i < ui->sect[s].nitem; i++)
      if (ui->sect[s].item[i].type == mjITEM_SEPARATOR) printf(" %d", ui->sect[s].item[i].state);
  printf("\n");
}

static void print_data(void) {
  printf("  data i");
  for (int i = 0; i < 12; i++) printf(" %d", ival[i]);
  printf(" b %d %d n", bval[0], bval[1]);
  for (int i = 0; i < 16; i++) printf(" %.17g", nval[i]);
  printf(" t '%s' '%s' key %d\n", tval, tval2, st.key);
}

static void render_frame(const char* what) {
  mjr_rectangle(st.rect[0], 0.1f, 0.2f, 0.3f, 1);
  mjui_render(&ui0, &st, &con);
  mjui_render(&ui1, &st, &con);
  mjr_readPixels(rgb, NULL, st.rect[0], &con);
  int n = st.rect[0].width * st.rect[0].height;
  printf("frame %d %s pixels %016llx\n", frame, what, fnv(rgb, 3 * (size_t)n));
  if (dumpdir) {
    char path[512];
    snprintf(path, sizeof(path), "%s/f%04d.ppm", dumpdir, frame);
    FILE* f = fopen(path, "wb");
    if (f) {
      fprintf(f, "P6\n%d %d\n255\n", st.rect[0].width, st.rect[0].height);
      for (int y = st.rect[0].height - 1; y >= 0; y--)
        fwrite(rgb + 3 * y * st.rect[0].width, 3, st.rect[0].width, f);
      fclose(f);
    }
  }
  frame++;
}

// ------------------------------------------------------------------ mjuiState as simulate fills it

static void layout(int height) {
  st.nrect = 4;
  st.rect[0] = (mjrRect){0, 0, W, height};
  st.rect[1] = (mjrRect){0, 0, ui0.width, height};
  st.rect[2] = (mjrRect){mjMAX(0, W - ui1.width), 0, ui1.width, height};
  st.rect[3] = (mjrRect){ui0.width, 0, mjMAX(0, W - ui0.width - ui1.width), height};
}

static int mods_ctrl, mods_shift, mods_alt, down_left, down_right;

static void update_state(double x, double y) {
  st.left = down_left;
  st.right = down_right;
  st.middle = 0;
  st.control = mods_ctrl;
  st.shift = mods_shift;
  st.alt = mods_alt;
  st.dx = x - st.x;
  st.dy = y - st.y;
  st.x = x;
  st.y = y;
  st.mouserect = mjr_findRect(mju_round(x), mju_round(y), st.nrect - 1, st.rect + 1) + 1;
}

static void dispatch(const char* what) {
  printf("event %s type %d at %g %g d %g %g rect %d drag %d %d dbl %d\n", what, st.type, st.x,
         st.y, st.dx, st.dy, st.mouserect, st.dragrect, st.dragbutton, st.doubleclick);
  if (st.dragrect == ui0.rectid || (st.dragrect == 0 && st.mouserect == ui0.rectid) ||
      st.type == mjEVENT_KEY) {
    print_item("ui0", mjui_event(&ui0, &st, &con));
  }
  if (st.dragrect == ui1.rectid || (st.dragrect == 0 && st.mouserect == ui1.rectid) ||
      st.type == mjEVENT_KEY) {
    print_item("ui1", mjui_event(&ui1, &st, &con));
  }
  printf("\n");
  print_ui("ui0", &ui0);
  print_ui("ui1", &ui1);
  print_data();
  render_frame(what);
}

static void press(double x, double y, int button) {
  if (button == mjBUTTON_LEFT) down_left = 1;
  if (button == mjBUTTON_RIGHT) down_right = 1;
  update_state(x, y);
  st.doubleclick = (button == st.button && now - st.buttontime < 0.25);
  st.type = mjEVENT_PRESS;
  st.button = button;
  st.buttontime = now;
  if (st.mouserect) {
    st.dragbutton = st.button;
    st.dragrect = st.mouserect;
  }
  dispatch("press");
  now += 1;
}

static void release(double x, double y, int button) {
  if (button == mjBUTTON_LEFT) down_left = 0;
  if (button == mjBUTTON_RIGHT) down_right = 0;
  update_state(x, y);
  st.type = mjEVENT_RELEASE;
  dispatch("release");
  st.dragrect = 0;
  st.dragbutton = 0;
  now += 0.01;
}

static void move(double x, double y) {
  if (!down_left && !down_right) return;
  update_state(x, y);
  st.type = mjEVENT_MOVE;
  dispatch("move");
}

static void click(double x, double y) {
  press(x, y, mjBUTTON_LEFT);
  release(x, y, mjBUTTON_LEFT);
}

static void wheel(double x, double y, double sy) {
  update_state(x, y);
  st.type = mjEVENT_SCROLL;
  st.sx = 0;
  st.sy = sy;
  dispatch("scroll");
}

static void key(int k, int ctrl, int shift, int alt) {
  mods_ctrl = ctrl;
  mods_shift = shift;
  mods_alt = alt;
  update_state(st.x, st.y);
  st.type = mjEVENT_KEY;
  st.key = k;
  st.keytime = now;
  dispatch("key");
  mods_ctrl = mods_shift = mods_alt = 0;
  now += 0.1;
}

static void resize_window(int height) {
  layout(height);
  update_state(st.x, st.y);
  st.type = mjEVENT_RESIZE;
  st.dragbutton = 0;
  st.dragrect = 0;
  dispatch("resize");
}

// window position at fraction (fx, fy) of rectangle r of the UI shown in its rect
static void at(mjUI* ui, mjrRect r, double fx, double fy, double* x, double* y) {
  mjrRect rect = st.rect[ui->rectid];
  double ux = r.left + fx * r.width;
  double uy = r.bottom + fy * r.height;
  *x = ux + rect.left;
  *y = uy + (rect.height - ui->height) + rect.bottom + (ui->height > rect.height ? ui->scroll : 0);
}

static mjrRect item_rect(mjUI* ui, int s, int i) {
  return i < 0 ? ui->sect[s].rtitle : ui->sect[s].item[i].rect;
}

// scrolls the UI with the wheel so that its rectangle r is in the middle of the window if
// it is not visible
static void reveal(mjUI* ui, mjrRect r) {
  double x, y;
  at(ui, r, 0.5, 0.5, &x, &y);
  mjrRect rect = st.rect[ui->rectid];
  if (ui->height <= rect.height || (y > rect.bottom + 5 && y < rect.bottom + rect.height - 5)) {
    return;
  }
  double uy = r.bottom + 0.5 * r.height;
  double target = 0.5 * rect.height - uy - rect.height + ui->height;
  int line = mju_round(ui->spacing.linescroll * 0.01 * con.fontScale);
  wheel(rect.left + 5, rect.bottom + 5, (ui->scroll - target) / line);
}

static void click_item(mjUI* ui, int s, int i, double fx, double fy) {
  double x, y;
  reveal(ui, item_rect(ui, s, i));
  at(ui, item_rect(ui, s, i), fx, fy, &x, &y);
  click(x, y);
}

static void press_item(mjUI* ui, int s, int i, double fx, double fy) {
  double x, y;
  reveal(ui, item_rect(ui, s, i));
  at(ui, item_rect(ui, s, i), fx, fy, &x, &y);
  press(x, y, mjBUTTON_LEFT);
}

static void move_item(mjUI* ui, int s, int i, double fx, double fy) {
  double x, y;
  at(ui, item_rect(ui, s, i), fx, fy, &x, &y);
  move(x, y);
}

static void release_item(mjUI* ui, int s, int i, double fx, double fy) {
  double x, y;
  at(ui, item_rect(ui, s, i), fx, fy, &x, &y);
  release(x, y, mjBUTTON_LEFT);
}

static void type_text(const char* s, int shift) {
  for (; *s; s++) key(*s, 0, shift, 0);
}

// ------------------------------------------------------------------ the script

static void script(void) {
  double x, y;

  // shortcut help with the right button, on both panels
  at(&ui0, ui0.sect[0].rtitle, 0.5, 0.5, &x, &y);
  press(x, y, mjBUTTON_RIGHT);
  move(x + 3, y - 2);
  release(x + 3, y - 2, mjBUTTON_RIGHT);
  at(&ui1, ui1.sect[1].rtitle, 0.5, 0.5, &x, &y);
  press(x, y, mjBUTTON_RIGHT);
  release(x, y, mjBUTTON_RIGHT);
  press(x, y, mjBUTTON_MIDDLE);
  release(x, y, mjBUTTON_MIDDLE);

  // section titles: collapse and expand each
  for (int s = 0; s < ui0.nsect; s++) {
    click_item(&ui0, s, -1, 0.3, 0.5);
    click_item(&ui0, s, -1, 0.3, 0.5);
  }
  // double click: all sections like this one (closed), then open all
  wheel(5, 5, 1000);
  at(&ui0, ui0.sect[0].rtitle, 0.5, 0.5, &x, &y);
  press(x, y, mjBUTTON_LEFT);
  release(x, y, mjBUTTON_LEFT);
  now = st.buttontime + 0.1;
  press(x, y, mjBUTTON_LEFT);
  release(x, y, mjBUTTON_LEFT);
  now += 1;
  click(x, y);
  now = st.buttontime + 0.1;
  press(x, y, mjBUTTON_LEFT);
  release(x, y, mjBUTTON_LEFT);
  now += 1;

  // buttons: press, move within and out, release; disabled button
  press_item(&ui0, 0, 0, 0.5, 0.5);
  move_item(&ui0, 0, 0, 0.6, 0.4);
  move_item(&ui0, 0, 1, 0.5, 0.5);
  release_item(&ui0, 0, 1, 0.5, 0.5);
  click_item(&ui0, 0, 2, 0.5, 0.5);
  click_item(&ui0, 0, 3, 0.5, 0.5);
  click_item(&ui0, 0, 4, 0.02, 0.05);  // corner of the oval: outside
  click_item(&ui0, 0, 4, 0.5, 0.5);

  // checks
  for (int i = 2; i < 6; i++) {
    click_item(&ui0, 1, i, 0.5, 0.5);
  }
  click_item(&ui0, 1, 2, 0.9, 0.1);

  // select boxes: open, hover, choose; open and release outside
  for (int i = 0; i < 2; i++) {
    int n = ui0.sect[1].item[i].multi.nelem;
    press_item(&ui0, 1, i, 0.5, 0.5);
    for (int k = 0; k < n; k++) move_item(&ui0, 1, i, 0.5, -0.5 - k);
    release_item(&ui0, 1, i, 0.5, -0.5 - (n - 1));
    press_item(&ui0, 1, i, 0.5, 0.5);
    move_item(&ui0, 1, i, 0.5, -1.5);
    release_item(&ui0, 1, i, 1.5, 0.5);
    press_item(&ui0, 1, i, 0.5, 0.5);
    release_item(&ui0, 1, i, 0.3, -0.5);
  }

  // sliders: press, drag, beyond the ends, release
  for (int i = 6; i < 8; i++) {
    press_item(&ui0, 1, i, 0.3, 0.5);
    move_item(&ui0, 1, i, 0.55, 0.5);
    move_item(&ui0, 1, i, 0.71, 0.7);
    move_item(&ui0, 1, i, 1.4, 0.5);
    move_item(&ui0, 1, i, -0.2, 2.0);
    move_item(&ui0, 1, i, 0.123, 0.5);
    release_item(&ui0, 1, i, 0.123, 0.5);
  }

  // radio, radioline
  for (int k = 0; k < 2; k++) click_item(&ui0, 2, 0, 0.25 + 0.5 * k, 0.5);
  for (int k = 0; k < 6; k++) click_item(&ui0, 2, 1, 0.1 + 0.45 * (k % 2), 0.1 + 0.3 * (k / 2));
  click_item(&ui0, 2, 1, 0.9, 0.05);
  for (int k = 0; k < 9; k++) click_item(&ui0, 2, 2, 0.05 + 0.11 * k, 0.5);

  // number sliders, a disabled one
  press_item(&ui0, 2, 4, 0.4, 0.5);
  move_item(&ui0, 2, 4, 0.8, 0.5);
  release_item(&ui0, 2, 4, 0.8, 0.5);
  click_item(&ui0, 2, 5, 0.77, 0.5);

  // separators: collapse, expand, open the closed one, its items
  click_item(&ui0, 2, 3, 0.5, 0.5);
  click_item(&ui0, 2, 3, 0.5, 0.5);
  click_item(&ui0, 2, 6, 0.5, 0.5);
  click_item(&ui0, 2, 7, 0.5, 0.5);
  click_item(&ui0, 2, 9, 0.8, 0.5);
  click_item(&ui0, 2, 6, 0.5, 0.5);

  // text edit: click, type, cursor keys, delete, backspace, enter
  click_item(&ui0, 3, 0, 0.5, 0.5);
  key(mjKEY_END, 0, 0, 0);
  type_text("AbC", 0);
  type_text("X-=[]\\;',./`", 1);
  key(127, 0, 0, 0);
  key(128, 0, 0, 0);
  key(mjKEY_LEFT, 0, 0, 0);
  key(mjKEY_LEFT, 0, 0, 0);
  key(mjKEY_LEFT, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  key(mjKEY_DELETE, 0, 0, 0);
  key(mjKEY_HOME, 0, 0, 0);
  key(mjKEY_DELETE, 0, 0, 0);
  key(mjKEY_RIGHT, 1, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  key(mjKEY_LEFT, 1, 0, 0);
  key(mjKEY_RIGHT, 0, 0, 0);
  key(mjKEY_UP, 0, 0, 0);
  key(290, 0, 0, 0);
  key(mjKEY_ENTER, 0, 0, 0);

  // long text: scrolling within the box; click in the text, drag the cursor
  click_item(&ui0, 3, 1, 0.5, 0.5);
  type_text("the quick brown fox jumps over the lazy dog", 0);
  key(mjKEY_HOME, 0, 0, 0);
  for (int k = 0; k < 6; k++) key(mjKEY_RIGHT, 0, 0, 0);
  key(mjKEY_END, 0, 0, 0);
  press_item(&ui0, 3, 1, 0.4, 0.5);
  move_item(&ui0, 3, 1, 0.6, 0.5);
  move_item(&ui0, 3, 1, 1.2, 0.5);
  move_item(&ui0, 3, 1, -0.2, 0.5);
  move_item(&ui0, 3, 1, 0.35, 0.5);
  release_item(&ui0, 3, 1, 0.35, 0.5);
  click_item(&ui0, 3, 1, 0.97, 0.5);
  key(mjKEY_ESCAPE, 0, 0, 0);

  // int edit: invalid and valid values; commit by clicking elsewhere
  click_item(&ui0, 3, 2, 0.5, 0.5);
  key(mjKEY_END, 0, 0, 0);
  type_text("7", 0);
  key(320 + 4, 0, 0, 0);
  type_text(" 1", 0);
  key(mjKEY_ENTER, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  key('.', 0, 0, 0);
  key('e', 0, 0, 0);
  key(mjKEY_ENTER, 0, 0, 0);
  click_item(&ui0, 3, 3, 0.5, 0.5);
  key(mjKEY_END, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  type_text("9", 0);
  click_item(&ui0, 3, 3, 0.5, 0.5);
  key(mjKEY_END, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  key(mjKEY_BACKSPACE, 0, 0, 0);
  type_text("=4", 0);
  click_item(&ui0, 3, 4, 0.2, 0.5);

  // number edit: ranges, exponents, escape, commit by clicking a title
  key(mjKEY_END, 0, 0, 0);
  for (int k = 0; k < 12; k++) key(mjKEY_BACKSPACE, 0, 0, 0);
  type_text("0.5 -1", 0);
  key(' ', 0, 0, 0);
  type_text("1e", 0);
  type_text("-1", 0);
  key(mjKEY_ENTER, 0, 0, 0);
  click_item(&ui0, 3, 4, 0.5, 0.5);
  key(mjKEY_LEFT, 1, 0, 0);
  type_text("3", 0);
  key(mjKEY_ENTER, 0, 0, 0);
  key(mjKEY_DELETE, 0, 0, 0);
  type_text("1.5E", 0);
  type_text("+0.", 0);
  click_item(&ui0, 1, -1, 0.5, 0.5);
  click_item(&ui0, 1, -1, 0.5, 0.5);
  click_item(&ui0, 3, 4, 0.5, 0.5);
  key(mjKEY_RIGHT, 1, 0, 0);
  for (int k = 0; k < 30; k++) key(mjKEY_BACKSPACE, 0, 0, 0);
  type_text("0.25 -1.5 0", 0);
  key(mjKEY_ENTER, 0, 0, 0);
  click_item(&ui0, 3, 5, 0.5, 0.5);
  click_item(&ui0, 3, 6, 0.5, 0.5);
  click_item(&ui0, 3, 7, 0.5, 0.5);

  // predicates: enable category 3, disable 2
  enable3 = 1;
  enable2 = 0;
  mjui_update(-1, -1, &ui0, &st, &con);
  mjui_update(-1, -1, &ui1, &st, &con);
  render_frame("predicates");
  click_item(&ui0, 1, 2, 0.5, 0.5);
  click_item(&ui0, 1, 3, 0.5, 0.5);
  click_item(&ui0, 0, 3, 0.5, 0.5);
  click_item(&ui0, 3, 5, 0.5, 0.5);
  type_text("12", 0);
  key(mjKEY_ENTER, 0, 0, 0);
  click_item(&ui0, 2, 5, 0.25, 0.5);
  key(290, 0, 0, 0);
  key(291, 0, 0, 0);
  key('D', 1, 0, 0);
  key('M', 1, 0, 0);
  enable2 = 1;

  // keyboard shortcuts: sections, buttons, checks, no match
  key('O', 0, 0, 1);
  key('W', 0, 0, 1);
  key('J', 0, 0, 1);
  key(292, 0, 0, 0);
  key(293, 0, 1, 0);
  key(293, 0, 0, 0);
  key('M', 1, 0, 0);
  key(300, 0, 1, 0);
  key('Q', 1, 1, 0);
  key('S', 0, 0, 1);
  key('F', 0, 0, 1);
  key('C', 0, 0, 1);

  // right panel: wheel, scrollbar drag and clicks on the bar, resize
  at(&ui1, ui1.sect[1].item[1].rect, 0.5, 0.5, &x, &y);
  wheel(x, y, -1);
  wheel(x, y, -3);
  wheel(x, y, -50);
  wheel(x, y, 2);
  click_item(&ui1, 0, -1, 0.5, 0.5);
  click_item(&ui1, 1, 3, 0.6, 0.5);
  {
    mjrRect r = st.rect[ui1.rectid];
    double bx = r.left + r.width - 3;
    if (ui1.height > r.height) {
      int w = mju_round(ui1.spacing.scroll * 0.01 * con.fontScale);
      double tstart = (double)ui1.scroll / ui1.height;
      double tend = (double)(ui1.scroll + r.height) / ui1.height;
      double ty = r.bottom + r.height * (1 - 0.5 * (tstart + tend));
      bx = r.left + r.width - 0.5 * w;
      press(bx, ty, mjBUTTON_LEFT);
      move(bx, ty - 40);
      move(bx + 20, ty - 100);
      move(bx, ty + 500);
      release(bx, ty + 500, mjBUTTON_LEFT);
      click(bx, r.bottom + 2);
      click(bx, r.bottom + r.height - 2);
    }
    click(bx, r.bottom + 5);
  }
  wheel(x, y, -2.5);
  resize_window(H - 300);
  wheel(x, y, -100);
  resize_window(H - 100);
  resize_window(H);
  press_item(&ui1, 1, 1, 0.9, 0.5);
  move_item(&ui1, 1, 1, 0.1, 0.5);
  release_item(&ui1, 1, 1, 0.1, 0.5);
  click_item(&ui1, 1, 0, 0.5, 0.5);
  click_item(&ui1, 0, 0, 0.5, 0.5);
  click_item(&ui1, 0, 2, 0.5, 0.5);
  click_item(&ui1, 0, 0, 0.5, 0.5);

  // an edit abandoned by a press on the other panel, and by the scrollbar of its own
  click_item(&ui0, 3, 0, 0.5, 0.5);
  type_text("z", 0);
  click_item(&ui1, 1, 2, 0.5, 0.5);
  print_ui("ui0", &ui0);
  wheel(5, 5, -1);
  click(5, 5);
}

int main(int argc, char** argv) {
  if (argc > 1) dumpdir = argv[1];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  int scales[] = {100, 150, 200, 100};
  for (int c = 0; c < 4; c++) {
    memset(ival, 0, sizeof(ival));
    memset(bval, 0, sizeof(bval));
    for (int i = 0; i < 16; i++) nval[i] = 0.1 * i - 0.35;
    ival[0] = c % 2;
    ival[1] = c;
    ival[6] = 2;
    ival[7] = 1;
    ival[10] = 3;
    strcpy(tval, "qpos");
    tval2[0] = 0;
    enable2 = 1;
    enable3 = 0;
    memset(&st, 0, sizeof(st));
    now = 100;

    mjr_defaultContext(&con);
    mjr_makeContext(NULL, &con, scales[c]);
    printf("config %d scale %d charHeight %d\n", c, scales[c], con.charHeight);
    memset(&ui0, 0, sizeof(mjUI));
    memset(&ui1, 0, sizeof(mjUI));
    ui0.spacing = mjui_themeSpacing(c % 2);
    ui0.color = mjui_themeColor(c);
    ui0.predicate = predicate;
    ui0.rectid = 1;
    ui0.auxid = 0;
    ui1.spacing = mjui_themeSpacing(c % 2);
    ui1.color = mjui_themeColor(c);
    ui1.predicate = c == 3 ? NULL : predicate;
    ui1.rectid = 2;
    ui1.auxid = 1;
    ui1.radiocol = c == 2 ? 3 : 0;
    ui0.radiocol = c == 2 ? 3 : 0;
    mjui_add(&ui0, defs0);
    mjui_add(&ui1, defs1);
    mjuiDef extra[] = {
      {mjITEM_CHECKBYTE, "Extra 1", 2, bval + 2, ""},
      {mjITEM_CHECKBYTE, "Extra 2", 2, bval + 3, ""},
      {mjITEM_END}
    };
    mjui_addToSection(&ui1, 1, extra);
    mjUI* uis[2] = {&ui0, &ui1};
    for (int u = 0; u < 2; u++) {
      mjui_resize(uis[u], &con);
      mjr_addAux(uis[u]->auxid, uis[u]->width, uis[u]->maxheight, uis[u]->spacing.samples,
                 &con);
      layout(H);
      mjui_update(-1, -1, uis[u], &st, &con);
    }
    render_frame("initial");
    for (int s = 0; s < ui0.nsect; s++) {
      mjui_update(s, -1, &ui0, &st, &con);
      mjui_update(s, 0, &ui0, &st, &con);
    }
    render_frame("sections");
    script();
    mjr_freeContext(&con);
  }
  printf("frames %d\n", frame);
  OSMesaDestroyContext(ctx);
  return 0;
}
