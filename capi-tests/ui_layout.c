// The UI framework without OpenGL: built-in themes, mjui_add / mjui_addToSection of a table
// with every item type (simulate's kind of panels), mjui_resize at every font scale, spacing
// and radio column count. Prints the mjUI bytes (pointers cleared) as hex.

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

static void hex(const char* what, const void* p, size_t n) {
  const unsigned char* b = p;
  unsigned long h = 1469598103934665603ul;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ul;
  printf("%s: %zu bytes fnv %016lx\n", what, n, h);
}

static int ival[8];
static mjtByte bval[8];
static mjtNum nval[8];
static char tval[300] = "text";

static void dump(const char* what, mjUI* ui) {
  static mjUI copy;
  memcpy(&copy, ui, sizeof(mjUI));
  copy.predicate = NULL;
  copy.userdata = NULL;
  copy.editchanged = NULL;
  for (int s = 0; s < mjMAXUISECT; s++)
    for (int i = 0; i < mjMAXUIITEM; i++) copy.sect[s].item[i].pdata = NULL;
  hex(what, &copy, sizeof(mjUI));
  printf("  width %d height %d maxheight %d nsect %d\n", ui->width, ui->height, ui->maxheight,
         ui->nsect);
  for (int s = 0; s < ui->nsect; s++) {
    mjuiSection* se = ui->sect + s;
    printf("  sect %d '%s' state %d mod %d key %d nitem %d title %d %d %d %d content %d %d %d %d\n",
           s, se->name, se->state, se->modifier, se->shortcut, se->nitem, se->rtitle.left,
           se->rtitle.bottom, se->rtitle.width, se->rtitle.height, se->rcontent.left,
           se->rcontent.bottom, se->rcontent.width, se->rcontent.height);
    for (int i = 0; i < se->nitem; i++) {
      mjuiItem* it = se->item + i;
      printf("    item %d type %d '%s' rect %d %d %d %d\n", i, it->type, it->name, it->rect.left,
             it->rect.bottom, it->rect.width, it->rect.height);
    }
  }
}

static void on_error(const char* msg) {
  printf("error: %s\n", msg);
  exit(0);
}

// bad definition tables: each must stop with 2.2.2's message
static mjuiDef bad[][3] = {
  {{mjITEM_BUTTON, "No section", 2, NULL, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "A section name of exactly 39 characters", 1, NULL, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 3, NULL, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, "X"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, "QA"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, " #x"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, " ab"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_BUTTON, "B", -1, NULL, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_CHECKINT, "C", 2, NULL, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_BUTTON, "B", 2, ival, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_SLIDERNUM, "N", 2, nval, "1"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_EDITNUM, "E", 2, nval, ""}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_EDITNUM, "E", 2, nval, "9"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_EDITNUM, "E", 2, nval, "2 0 1"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_RADIO, "R", 2, ival, "a\n\nb"}, {mjITEM_END}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_STATIC, "R", 2, NULL, "x"}, {17, "?", 2, NULL, ""}},
  {{mjITEM_SECTION, "S", 1, NULL, ""}, {mjITEM_SLIDERINT, "I", 2, ival, "3 1"}, {mjITEM_END}},
};

int main(int argc, char** argv) {
  if (argc > 1) {
    int k = atoi(argv[1]);
    if (k < 0 || k >= (int)(sizeof(bad) / sizeof(bad[0]))) return 2;
    static mjUI ui;
    mju_user_error = on_error;
    mjui_add(&ui, bad[k]);
    printf("no error: nsect %d\n", ui.nsect);
    if (ui.nsect) {
      mjuiItem* it = ui.sect[0].item;
      printf("nitem %d slider %.17g %.17g %.17g\n", ui.sect[0].nitem, it[0].slider.range[0],
             it[0].slider.range[1], it[0].slider.divisions);
    }
    return 0;
  }
  for (int i = 0; i < 2; i++) {
    mjuiThemeSpacing s = mjui_themeSpacing(i);
    hex("spacing", &s, sizeof(s));
  }
  for (int i = -1; i < 5; i++) {
    mjuiThemeColor c = mjui_themeColor(i);
    hex("color", &c, sizeof(c));
  }

  mjuiDef defs[] = {
    {mjITEM_SECTION, "File", 1, NULL, "AF"},
    {mjITEM_BUTTON, "Save xml", 2, NULL, ""},
    {mjITEM_BUTTON, "Save mjb", 2, NULL, ""},
    {mjITEM_BUTTON, "Print model", 2, NULL, "CM"},
    {mjITEM_BUTTON, "Print data", 2, NULL, "CD"},
    {mjITEM_BUTTON, "Quit", 1, NULL, "CQ"},
    {mjITEM_SECTION, "Option", 0, NULL, "AO"},
    {mjITEM_SELECT, "Spacing", 1, ival + 0, "Tight\nWide"},
    {mjITEM_SELECT, "Color", 1, ival + 1, "Default\nOrange\nWhite\nBlack"},
    {mjITEM_CHECKINT, "Help", 2, ival + 2, " #290"},
    {mjITEM_CHECKINT, "Info", 2, ival + 3, " #291"},
    {mjITEM_CHECKBYTE, "Profiler", 2, bval + 0, " #292"},
    {mjITEM_SLIDERINT, "Refresh", 3, ival + 4, "0 100"},
    {mjITEM_SECTION, "Simulation", 1, NULL, "AS"},
    {mjITEM_RADIO, "", 2, ival + 5, "Pause\nRun"},
    {mjITEM_RADIO, "Modes", 2, ival + 6, "A\nB\nC\nD\nE"},
    {mjITEM_RADIOLINE, "Line", 2, ival + 7, "X\nY\nZ"},
    {mjITEM_SEPARATOR, "Noise", 1, NULL, ""},
    {mjITEM_SLIDERNUM, "Scale", 2, nval + 0, "0 2"},
    {mjITEM_SLIDERNUM, "Rate", 2, nval + 1, "0 2 50"},
    {mjITEM_SEPARATOR, "Closed", mjSEPCLOSED, NULL, ""},
    {mjITEM_CHECKINT, "Hidden a", 2, ival + 2, ""},
    {mjITEM_CHECKINT, "Hidden b", 2, ival + 3, ""},
    {mjITEM_SLIDERINT, "Hidden c", 2, ival + 4, "0 10 5"},
    {mjITEM_SECTION, "Watch", 0, NULL, "AW"},
    {mjITEM_EDITTXT, "Field", 2, tval, "qpos"},
    {mjITEM_EDITINT, "Index", 2, ival + 0, "1"},
    {mjITEM_EDITNUM, "Vec", 2, nval + 2, "3 -1 1 -2 2 0 0"},
    {mjITEM_STATIC, "Value", 2, NULL, " "},
    {mjITEM_STATIC, "Lines", 2, NULL, "one\ntwo\nthree"},
    {mjITEM_STATIC, "", 2, NULL, "unnamed"},
    {mjITEM_SECTION, "Hidden title", 2, NULL, ""},
    {mjITEM_BUTTON, "Alone", 2, NULL, "S#300"},
    {mjITEM_END}
  };
  mjuiDef extra[] = {
    {mjITEM_CHECKBYTE, "Extra 1", 2, bval + 1, ""},
    {mjITEM_CHECKBYTE, "Extra 2", 2, bval + 2, ""},
    {mjITEM_END}
  };

  static mjUI ui;
  static mjrContext con;
  int scales[] = {50, 100, 150, 200, 250, 300};
  for (int sp = 0; sp < 2; sp++) {
    for (int rc = 0; rc < 4; rc += 3) {
      memset(&ui, 0, sizeof(mjUI));
      ui.spacing = mjui_themeSpacing(sp);
      ui.color = mjui_themeColor(sp + 1);
      ui.radiocol = rc;
      mjui_add(&ui, defs);
      mjui_addToSection(&ui, 2, extra);
      for (int k = 0; k < 6; k++) {
        memset(&con, 0, sizeof(con));
        con.fontScale = scales[k];
        con.charHeight = 8 + 3 * k;
        mjui_resize(&ui, &con);
        char what[64];
        snprintf(what, sizeof(what), "ui spacing %d radiocol %d scale %d", sp, rc, scales[k]);
        dump(what, &ui);
      }
    }
  }
  return 0;
}
