// Default warning output (tests/print_vfs.rs): with no handler installed, warnings print to
// stdout and append dated entries to MUJOCO_LOG.TXT in the working directory. Prints what
// went to stdout, then the log with each date line replaced by DATE.
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <string.h>

static void length_of(const char* msg) { printf("handler got %zu bytes\n", strlen(msg)); }

int main(void) {
  remove("MUJOCO_LOG.TXT");
  mju_warning("a plain warning");
  mju_warning_i("a warning with the number %d", 7);
  static char longtext[1500];
  memset(longtext, 'x', sizeof longtext - 1);
  mju_warning_s("a long warning: %s", longtext);  // formatted into a 1000-byte buffer
  mju_warning(longtext);
  mju_user_warning = length_of;
  mju_warning(longtext);
  mju_warning_s("a long warning: %s", longtext);
  mju_warning_i("a warning with the number %d", 7);
  mju_user_warning = NULL;

  // the engine's own: a model made unstable, reset by mj_step
  FILE* f = fopen("warning_log.xml", "w");
  if (!f) return 1;
  fputs("<mujoco><worldbody><body><freejoint/><geom size='.1'/></body></worldbody></mujoco>", f);
  fclose(f);
  char err[1000];
  mjModel* m = mj_loadXML("warning_log.xml", NULL, err, sizeof err);
  if (!m) {
    printf("load error: %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  d->qvel[0] = 1e20;
  mj_step(m, d);
  printf("time after reset %g, bad qvel warnings %d\n", d->time,
         d->warning[mjWARN_BADQVEL].number);
  mj_deleteData(d);
  mj_deleteModel(m);
  fflush(stdout);

  printf("--- MUJOCO_LOG.TXT\n");
  f = fopen("MUJOCO_LOG.TXT", "r");
  if (!f) {
    printf("(no log)\n");
    return 0;
  }
  char line[4000];
  while (fgets(line, sizeof line, f)) {
    // asctime: "Sat Nov 28 17:25:04 2026\n"
    int date = strlen(line) == 25 && line[13] == ':' && line[16] == ':';
    fputs(date ? "DATE\n" : line, stdout);
  }
  fclose(f);
  remove("MUJOCO_LOG.TXT");
  remove("warning_log.xml");
  return 0;
}
