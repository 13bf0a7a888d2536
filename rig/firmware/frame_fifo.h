/* Frames from the sampling interrupt to the USB sender: a single-producer single-consumer ring
 * (one-byte indices, which the AVR reads and writes atomically), and the packets of PROTOCOL.md's
 * frame stream built from it. A full ring drops the newest frame: its sequence number is spent, so
 * the host sees the gap. */
#ifndef NIBRIG_FRAME_FIFO_H
#define NIBRIG_FRAME_FIFO_H

#include <stdint.h>

#include "rig_device.h"

#define FRAME_FIFO_SIZE 16u /* a power of two (the indices wrap at 256): two packets */
/* At most 8 frames a packet: 4 + 28·n is then never a multiple of 64 bytes, so a packet always ends
 * in a short USB packet and never needs a zero-length one. */
#define PACKET_MAX_FRAMES 8u
#define PACKET_MAX_BYTES (4u + PACKET_MAX_FRAMES * RIG_FRAME_BYTES)

struct frame_fifo {
  struct rig_frame frames[FRAME_FIFO_SIZE];
  volatile uint8_t head; /* written by the producer */
  volatile uint8_t tail; /* written by the consumer */
  volatile uint16_t dropped;
};

void frame_fifo_clear(struct frame_fifo *q);
uint8_t frame_fifo_count(const struct frame_fifo *q);
/* The producer's slot for the next frame, or 0 when full (the frame is dropped). */
struct rig_frame *frame_fifo_slot(struct frame_fifo *q);
void frame_fifo_push(struct frame_fifo *q);
/* The oldest frame's device time (the fifo must not be empty). */
uint64_t frame_fifo_oldest_us(const struct frame_fifo *q);

/* Whether to send now: a full packet's worth; or the oldest frame would wait `max_wait_us` before
 * the next frame (`period_us` after the newest) comes, so the packet leaves with the frame just made
 * and its newest frame reaches the host at once (the host's time base rests on the earliest
 * arrivals); or, whatever the frames, the oldest has waited `max_wait_us`. */
int frame_fifo_ready(const struct frame_fifo *q, uint64_t now_us, uint32_t max_wait_us, uint32_t period_us);
/* Moves up to PACKET_MAX_FRAMES frames into `out` as one packet; returns its length in bytes. */
uint16_t frame_fifo_take_packet(struct frame_fifo *q, uint8_t out[PACKET_MAX_BYTES]);

#endif
