/* MicroStrain's own MIP parser (mip_sdk's C mip_parser) over a file, for mip_vendor_compare.sh:
 * the same bytes navfuse_mip_bench_stream frames, read the same way (64 KiB chunks, the read
 * inside the timed span, in-process), so the two figures compare framers and nothing else.
 *
 *   mip_vendor_count FILE [RUNS]
 *
 * Prints, like navfuse_mip_bench_stream: "type SET N" per descriptor set of the packets the
 * parser accepted (first run), "frames N", and "median_s S mb_per_s R" (MB = 10^6 bytes).
 * Built by mip_vendor_compare.sh against an mip_sdk checkout; it is not part of the build. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "mip/mip_parser.h"

enum { kChunk = 65536, kMaxRuns = 99 };

typedef struct {
  uint64_t by_set[256];
  uint64_t frames;
} Counts;

static bool count_packet(void* context, const mip_packet* packet, timestamp_type timestamp) {
  (void)timestamp;
  Counts* c = (Counts*)context;
  ++c->by_set[mip_packet_descriptor_set(packet)];
  ++c->frames;
  return true;
}

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One pass; the timeout never fires (every chunk is handed over at time 0). */
static int run_once(const char* path, Counts* counts, uint64_t* bytes, double* seconds) {
  static uint8_t chunk[kChunk];
  uint8_t ring[1024]; /* a power of two, larger than the largest MIP packet (261 bytes) */
  const double t0 = now_s();
  FILE* f = fopen(path, "rb");
  if (f == NULL) return 1;
  mip_parser parser;
  mip_parser_init(&parser, ring, sizeof ring, count_packet, counts, 1000);
  size_t got;
  *bytes = 0;
  while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) {
    mip_parser_parse(&parser, chunk, got, 0, 0);
    *bytes += got;
  }
  fclose(f);
  *seconds = now_s() - t0;
  return 0;
}

static int by_value(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: mip_vendor_count FILE [RUNS]\n");
    return 2;
  }
  int runs = argc > 2 ? atoi(argv[2]) : 1;
  if (runs < 1) runs = 1;
  if (runs > kMaxRuns) runs = kMaxRuns;
  double times[kMaxRuns];
  Counts first;
  uint64_t bytes = 0;
  for (int i = 0; i < runs; ++i) {
    static Counts c;
    for (int s = 0; s < 256; ++s) c.by_set[s] = 0;
    c.frames = 0;
    if (run_once(argv[1], &c, &bytes, &times[i]) != 0) {
      fprintf(stderr, "cannot read %s\n", argv[1]);
      return 1;
    }
    if (i == 0) first = c;
  }
  qsort(times, (size_t)runs, sizeof times[0], by_value);
  const double median = times[runs / 2];
  for (int s = 0; s < 256; ++s)
    if (first.by_set[s] > 0) printf("type %d %llu\n", s, (unsigned long long)first.by_set[s]);
  printf("frames %llu\n", (unsigned long long)first.frames);
  printf("median_s %.4f mb_per_s %.1f\n", median, (double)bytes / median / 1e6);
  return 0;
}
