#include "frame_fifo.h"

#include <string.h>

void frame_fifo_clear(struct frame_fifo *q) { q->head = (uint8_t)(q->tail + q->packet_frames); }

uint8_t frame_fifo_count(const struct frame_fifo *q) { return (uint8_t)(q->head - q->tail); }

uint8_t *frame_fifo_slot(struct frame_fifo *q) {
  if (frame_fifo_count(q) >= FRAME_FIFO_SIZE) {
    ++q->dropped;
    return 0;
  }
  return q->frames[q->head % FRAME_FIFO_SIZE];
}

void frame_fifo_push(struct frame_fifo *q) { q->head = (uint8_t)(q->head + 1u); }

/* A frame's first 8 bytes: its device time, little-endian (rig_frame_encode), as the AVR and the
 * hosts the tests run on lay a uint64_t out: copied, as shifting 64 bits byte by byte costs the AVR
 * hundreds of cycles, twice a pass of its loop. */
static uint64_t frame_time_us(const uint8_t *frame) {
  uint64_t t;
  memcpy(&t, frame, sizeof t);
  return t;
}

uint64_t frame_fifo_oldest_us(const struct frame_fifo *q) { return frame_time_us(q->frames[q->tail % FRAME_FIFO_SIZE]); }

int frame_fifo_ready(const struct frame_fifo *q, uint64_t now_us, uint32_t max_wait_us, uint32_t period_us) {
  const uint8_t n = frame_fifo_count(q);
  if (n == 0) return 0;
  if (n >= PACKET_MAX_FRAMES) return 1;
  const uint64_t oldest = frame_fifo_oldest_us(q);
  const uint64_t newest = frame_time_us(q->frames[(uint8_t)(q->head - 1u) % FRAME_FIFO_SIZE]);
  return newest + period_us - oldest >= max_wait_us || now_us - oldest >= max_wait_us;
}

uint16_t frame_fifo_begin_packet(struct frame_fifo *q) {
  uint8_t n = frame_fifo_count(q);
  if (n > PACKET_MAX_FRAMES) n = PACKET_MAX_FRAMES;
  q->packet_frames = n;
  q->header[0] = n;
  q->header[1] = RIG_FRAME_BYTES;
  q->header[2] = q->header[3] = 0;
  q->header_sent = 0;
  q->sent_frames = 0;
  q->sent_bytes = 0;
  return (uint16_t)(RIG_PACKET_HEADER_BYTES + n * RIG_FRAME_BYTES);
}

uint8_t frame_fifo_packet_span(struct frame_fifo *q, const uint8_t **bytes) {
  if (q->packet_frames == 0) return 0;
  if (q->header_sent < RIG_PACKET_HEADER_BYTES) {
    *bytes = q->header + q->header_sent;
    return (uint8_t)(RIG_PACKET_HEADER_BYTES - q->header_sent);
  }
  *bytes = q->frames[(uint8_t)(q->tail + q->sent_frames) % FRAME_FIFO_SIZE] + q->sent_bytes;
  return (uint8_t)(RIG_FRAME_BYTES - q->sent_bytes);
}

void frame_fifo_packet_advance(struct frame_fifo *q, uint8_t n) {
  if (q->header_sent < RIG_PACKET_HEADER_BYTES) {
    q->header_sent = (uint8_t)(q->header_sent + n);
    return;
  }
  q->sent_bytes = (uint8_t)(q->sent_bytes + n);
  if (q->sent_bytes < RIG_FRAME_BYTES) return;
  q->sent_bytes = 0;
  if (++q->sent_frames == q->packet_frames) {
    q->tail = (uint8_t)(q->tail + q->packet_frames);
    q->packet_frames = 0;
  }
}

void frame_fifo_abandon_packet(struct frame_fifo *q) { q->packet_frames = 0; }
