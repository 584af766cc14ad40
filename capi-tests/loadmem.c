// Peak resident memory of loading a model: mj_loadXML, mj_deleteModel, then the process's
// high-water mark (VmHWM, kB) and the resident size after the load (VmRSS) on stdout.
//   loadmem FILE            one load
//   loadmem FILE CYCLES     CYCLES rounds of load, mj_makeData, one mj_step, delete both;
//                           the high-water mark and the resident size after the last round
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <mujoco/mujoco.h>

static long status_kb(const char* key) {
  FILE* f = fopen("/proc/self/status", "r");
  char line[256];
  long v = -1;
  while (f && fgets(line, sizeof line, f)) {
    if (!strncmp(line, key, strlen(key))) sscanf(line + strlen(key), "%ld", &v);
  }
  if (f) fclose(f);
  return v;
}

// Load/free rounds: the peak shows what the heap keeps and fragments between them.
static int cycles(const char* file, int n) {
  char err[1000] = "";
  for (int i = 0; i < n; i++) {
    mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
    if (!m) {
      printf("error: %s\n", err);
      return 1;
    }
    mjData* d = mj_makeData(m);
    mj_step(m, d);
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  printf("peak %ld rss %ld\n", status_kb("VmHWM:"), status_kb("VmRSS:"));
  return 0;
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  if (argc > 2) return cycles(argv[1], atoi(argv[2]));
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("error: %s\n", err);
    return 1;
  }
  long rss = status_kb("VmRSS:");
  mj_deleteModel(m);
  printf("peak %ld rss %ld\n", status_kb("VmHWM:"), rss);
  return 0;
}
