#include "frame_fifo.h"

#include <string.h>

void frame_fifo_clear(struct frame_fifo *q) {
  q->tail = q->head;
}

uint8_t frame_fifo_count(const struct frame_fifo *q) { return (uint8_t)(q->head - q->tail); }

struct rig_frame *frame_fifo_slot(struct frame_fifo *q) {
  if (frame_fifo_count(q) >= FRAME_FIFO_SIZE) {
    ++q->dropped;
    return 0;
  }
  return &q->frames[q->head % FRAME_FIFO_SIZE];
}

void frame_fifo_push(struct frame_fifo *q) { q->head = (uint8_t)(q->head + 1u); }

uint64_t frame_fifo_oldest_us(const struct frame_fifo *q) { return q->frames[q->tail % FRAME_FIFO_SIZE].t_us; }

int frame_fifo_ready(const struct frame_fifo *q, uint64_t now_us, uint32_t max_wait_us, uint32_t period_us) {
  const uint8_t n = frame_fifo_count(q);
  if (n == 0) return 0;
  if (n >= PACKET_MAX_FRAMES) return 1;
  const uint64_t oldest = frame_fifo_oldest_us(q);
  const uint64_t newest = q->frames[(uint8_t)(q->head - 1u) % FRAME_FIFO_SIZE].t_us;
  return newest + period_us - oldest >= max_wait_us || now_us - oldest >= max_wait_us;
}

uint16_t frame_fifo_take_packet(struct frame_fifo *q, uint8_t out[PACKET_MAX_BYTES]) {
  uint8_t n = frame_fifo_count(q);
  if (n > PACKET_MAX_FRAMES) n = PACKET_MAX_FRAMES;
  out[0] = n;
  out[1] = RIG_FRAME_BYTES;
  out[2] = out[3] = 0;
  for (uint8_t i = 0; i < n; ++i) {
    rig_frame_encode(&q->frames[q->tail % FRAME_FIFO_SIZE], out + 4 + i * RIG_FRAME_BYTES);
    q->tail = (uint8_t)(q->tail + 1u);
  }
  return (uint16_t)(4u + n * RIG_FRAME_BYTES);
}
