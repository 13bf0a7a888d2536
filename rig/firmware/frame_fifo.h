/* Frames from the sampling to the USB sender: a single-producer single-consumer ring of frames as
 * they go on the wire (one-byte indices, which the AVR reads and writes atomically), and the packets
 * of PROTOCOL.md's frame stream read straight out of it, so that no packet-sized copy takes the
 * chip's RAM. A full ring drops the newest frame: its sequence number is spent, so the host sees the
 * gap. */
#ifndef NIBRIG_FRAME_FIFO_H
#define NIBRIG_FRAME_FIFO_H

#include <stdint.h>

#include "rig_device.h"

#define FRAME_FIFO_SIZE 16u /* a power of two (the indices wrap at 256): two packets */
/* At most 8 frames a packet: 4 + 28·n is then never a multiple of 64 bytes, so a packet always ends
 * in a short USB packet and never needs a zero-length one. */
#define PACKET_MAX_FRAMES 8u
#define PACKET_MAX_BYTES (RIG_PACKET_HEADER_BYTES + PACKET_MAX_FRAMES * RIG_FRAME_BYTES)

struct frame_fifo {
  uint8_t frames[FRAME_FIFO_SIZE][RIG_FRAME_BYTES];
  volatile uint8_t head; /* written by the producer */
  volatile uint8_t tail; /* written by the consumer */
  volatile uint16_t dropped;
  /* The packet on its way: its frames from the tail on, and its next unsent byte. */
  uint8_t packet_frames; /* 0: none */
  uint8_t header[RIG_PACKET_HEADER_BYTES];
  uint8_t header_sent;   /* bytes of the header gone */
  uint8_t sent_frames;   /* of the packet's, all their bytes gone */
  uint8_t sent_bytes;    /* of the frame being sent */
};

/* Drops every frame but those of the packet on its way. */
void frame_fifo_clear(struct frame_fifo *q);
uint8_t frame_fifo_count(const struct frame_fifo *q);
/* The producer's slot for the next frame's 28 bytes, or 0 when full (the frame is dropped). */
uint8_t *frame_fifo_slot(struct frame_fifo *q);
void frame_fifo_push(struct frame_fifo *q);
/* The oldest frame's device time (the fifo must not be empty). */
uint64_t frame_fifo_oldest_us(const struct frame_fifo *q);

/* Whether to send now: a full packet's worth; or the oldest frame would wait `max_wait_us` before
 * the next frame (`period_us` after the newest) comes, so the packet leaves with the frame just made
 * and its newest frame reaches the host at once (the host's time base rests on the earliest
 * arrivals); or, whatever the frames, the oldest has waited `max_wait_us`. */
int frame_fifo_ready(const struct frame_fifo *q, uint64_t now_us, uint32_t max_wait_us, uint32_t period_us);

/* A packet of up to PACKET_MAX_FRAMES frames from the tail: its length in bytes. Its frames stay in
 * the ring until all its bytes are read. */
uint16_t frame_fifo_begin_packet(struct frame_fifo *q);
/* The next run of the packet's bytes that lie together (the header, or the rest of a frame), and
 * how many; 0 once the packet is all read (its frames then leave the ring). */
uint8_t frame_fifo_packet_span(struct frame_fifo *q, const uint8_t **bytes);
/* `n` bytes of that run were sent (at most its length). */
void frame_fifo_packet_advance(struct frame_fifo *q, uint8_t n);
/* The packet given up (a bus reset): its frames stay for the next. */
void frame_fifo_abandon_packet(struct frame_fifo *q);

#endif
