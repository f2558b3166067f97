/* Host harness for the responder: reads frames as `ID b0 b1 ...` (hex) one
 * per line from stdin, writes every frame the slave sends in reaction the same
 * way, and a line `.` after each input frame. argv[1]: the slave's MAC (decimal). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dn_responder.h"

int main(int argc, char **argv) {
  dn_slave slave;
  char line[256];
  dn_init(&slave, (uint8_t)(argc > 1 ? atoi(argv[1]) : 9));
  while (fgets(line, sizeof line, stdin) != NULL) {
    dn_frame in, out;
    char *p = line, *end;
    unsigned long v = strtoul(p, &end, 16);
    if (end == p) continue;
    memset(&in, 0, sizeof in);
    in.id = (uint16_t)v;
    for (p = end; in.len < 8u; p = end) {
      v = strtoul(p, &end, 16);
      if (end == p) break;
      in.data[in.len++] = (uint8_t)v;
    }
    if (dn_receive(&slave, &in, &out)) {
      unsigned i;
      printf("0x%03X", (unsigned)out.id);
      for (i = 0; i < out.len; ++i) printf(" %02X", (unsigned)out.data[i]);
      printf("\n");
    }
    printf(".\n");
  }
  return 0;
}
