/* The rig controller's firmware: the loop that joins the rig's protocol state, the speed loop, the
 * board and the USB device. Interrupts only capture (frames, milliseconds, encoder edges, ADC
 * conversions); everything else runs here. */
#include <avr/interrupt.h>
#include <avr/pgmspace.h>

#include "board.h"
#include "frame_fifo.h"
#include "rig_device.h"
#include "speed_loop.h"
#include "usb_device.h"

/* A packet leaves at the latest this long after its oldest frame was sampled (PROTOCOL.md allows
 * 10 ms): the bound on the stream's latency at any rate. */
#define STREAM_MAX_WAIT_US 4000u

static struct rig rig;
static struct frame_fifo fifo;
static struct speed_estimator estimator;
static struct speed_controller controller;
static struct motor_guard guard;
static uint16_t applied_rate;
static uint32_t frame_period_us; /* of applied_rate, divided once */
static uint8_t bootloader_asked;
static int32_t last_count;
static uint8_t driving; /* the motor had a target at the last tick */

static void on_vendor_request(const uint8_t setup[8], const uint8_t *data, struct rig_reply *reply) {
  if (data == 0 && !(setup[0] & 0x80) && (setup[6] | setup[7])) {
    rig_refuse(&rig, setup[1], RIG_REFUSE_LENGTH);
    reply->stall = 1;
    return;
  }
  rig_control(&rig, setup, data, (uint32_t)board_clock_us(), reply);
  if (reply->persist) board_persist_store_begin(&rig.persist);
}

/* Frames from the captured samples; the sequence also counts what the board could not capture. */
static void make_frames(void) {
  rig.sequence += board_take_lost_samples();
  struct board_sample s;
  while (board_take_sample(&s)) {
    struct rig_adc_means adc;
    /* Reciprocals instead of divisions: the AVR divides floats in software. In flash: RAM is short. */
    static const float per[9] PROGMEM = {0.0f, 1.0f, 1.0f / 2, 1.0f / 3, 1.0f / 4, 1.0f / 5, 1.0f / 6, 1.0f / 7, 1.0f / 8};
    for (uint8_t c = 0; c < 2; ++c) {
      /* No conversion this period (the highest rates): the channel holds its last mean. */
      static float last[2];
      const uint8_t n = s.conversions[c];
      if (n > 0) last[c] = (float)s.force_sum[c] * (n < 9 ? pgm_read_float(&per[n]) : 1.0f / (float)n);
      adc.force_counts[c] = last[c];
    }
    struct rig_frame f;
    rig_sample(&rig, s.t_us, &adc, &f);
    uint8_t *slot = rig.streaming ? frame_fifo_slot(&fifo) : 0;
    if (slot) {
      rig_frame_encode(&f, slot);
      frame_fifo_push(&fifo);
    }
    /* The endpoint takes 64 bytes at a time: between frames too, or at the highest rates the loop
     * cannot hand the USB controller the stream's bytes as fast as they are made. */
    usb_stream_service(&fifo);
  }
  if (rig.zero_taken) {
    rig.zero_taken = 0;
    board_persist_store_begin(&rig.persist);
  }
}

static void stream(void) {
  if (!rig.streaming) {
    frame_fifo_clear(&fifo);
  } else if (usb_device_configured() && usb_stream_idle() && frame_fifo_count(&fifo) > 0 &&
             frame_fifo_ready(&fifo, board_clock_us(), STREAM_MAX_WAIT_US, frame_period_us)) {
    frame_fifo_begin_packet(&fifo);
    usb_stream_start();
  }
  usb_stream_service(&fifo);
}

/* The guard's verdicts are PROTOCOL.md's fault causes. */
_Static_assert((int)MOTOR_STALL == RIG_CAUSE_STALL && (int)MOTOR_DISC_SLIPPING == RIG_CAUSE_SLIP &&
                   (int)MOTOR_ENCODER_SILENT == RIG_CAUSE_ENCODER_SILENT &&
                   (int)MOTOR_ENCODER_CHANNEL_LOST == RIG_CAUSE_ENCODER_CHANNEL,
               "motor_verdict and rig_fault_cause must agree");

static void run_speed_loop(void) {
  const uint8_t ms = board_take_ms();
  if (ms == 0) return;
  struct board_encoder e;
  board_encoder_read(&e);
  const uint32_t now = (uint32_t)board_clock_us(); /* after the encoder: its last edge is not later */
  rig.speed_mm_s = rig_speed_from_counts(&rig, speed_estimate(&estimator, e.count, e.last_edge_us, now));
  rig_tick_ms(&rig, now);
  const float target = rig_speed_target(&rig);
  /* A start wakes the driver with a pulse on nSLEEP: that clears a fault it latched. */
  if (target > 0.0f && !driving) board_driver_reset();
  driving = target > 0.0f;
  const float duty = speed_controller_step(&controller, target, rig.speed_mm_s, 1e-3f * (float)ms);
  /* The loop's longest pass: the stream's next 64 bytes go between its halves. */
  stream();
  const int32_t moved = e.count - last_count;
  last_count = e.count;
  const struct motor_look look = {
      .ms = ms,
      .duty = duty,
      .target = target,
      .measured = rig.speed_mm_s,
      .current_A = board_motor_current_A(),
      .driver_fault = (uint8_t)board_driver_fault(),
      .counts = (int16_t)(moved > 32767 ? 32767 : moved < -32767 ? -32767 : moved),
      .edges_a = e.edges_a,
      .edges_b = e.edges_b,
      .glitches = e.glitches,
      .normal_N = rig.force_N[0],
      .tangential_N = rig.force_N[1],
  };
  const enum motor_verdict verdict = motor_guard_check(&guard, &look);
  if (verdict != MOTOR_OK) rig_fault(&rig, (enum rig_fault_cause)verdict);
  board_motor(rig_speed_target(&rig) > 0.0f ? duty : 0.0f);
  board_led(rig_speed_target(&rig) > 0.0f);
}

int main(void) {
  struct rig_persist persist;
  board_init();
  const int persisted = board_persist_load(&persist);
  if (!persisted) {
    rig_persist_defaults(&persist);
    board_new_serial(persist.serial);
    board_persist_store_begin(&persist);
  }
  rig_init(&rig, &persist, (uint32_t)board_clock_us());
  rig.reset_cause = (uint8_t)board_reset_cause();
  if (!persisted) rig.health |= RIG_HEALTH_FACTORY_DEFAULTS;
  speed_controller_init(&controller);
  applied_rate = rig.frame_rate_hz;
  frame_period_us = 1000000ul / applied_rate;
  board_set_frame_rate(applied_rate);
  usb_device_init(on_vendor_request, rig.persist.serial);
  sei();
  for (;;) {
    board_kick_watchdog();
    switch (usb_device_poll()) {
      case USB_BUS_RESET: /* a new host asks for the stream itself */
        rig.streaming = 0;
        frame_fifo_abandon_packet(&fifo);
        break;
      case USB_BOOTLOADER_ASKED: bootloader_asked = 1; break;
      case USB_NOTHING: break;
    }
    if (rig.frame_rate_hz != applied_rate) {
      applied_rate = rig.frame_rate_hz;
      frame_period_us = 1000000ul / applied_rate;
      board_set_frame_rate(applied_rate);
    }
    make_frames();
    stream();
    run_speed_loop();
    stream();
    board_persist_store_step();
    if (bootloader_asked && usb_stream_idle()) board_enter_bootloader();
  }
}
