/* A C program with its own main that runs the part program linked into it. */
#include <runtime/ncrt.h>
#include <stdio.h>

int main(int argc, char **argv) {
  printf("simulator on ncc %s\n", ncrt_version());
  fflush(stdout);
  return ncrt_main(argc, argv, ncc_program_main, ncc_program_info);
}
