/* The reference controller's hardware (rig/HARDWARE.md's pin table): timer 3 as the device clock
 * and the frame and millisecond ticks, timer 1's PWM into the H-bridge, the encoder on INT0/INT1,
 * the ADC's force and current channels, the EEPROM, and the way into the bootloader. */
#ifndef NIBRIG_BOARD_H
#define NIBRIG_BOARD_H

#include <stdint.h>

#include "rig_device.h"

/* What the frame interrupt captured: its instant and the ADC's sums since the previous frame. */
struct board_sample {
  uint64_t t_us;
  uint32_t force_sum[2];
  uint8_t conversions[2];
};

void board_init(void);
/* What restarted the chip (rig_device.h's enum rig_reset), from its reset flags. */
uint8_t board_reset_cause(void);
uint64_t board_clock_us(void);
void board_set_frame_rate(uint16_t hz);
/* The next captured sample, or 0 when none waits; samples lost to a full ring are counted. */
int board_take_sample(struct board_sample *s);
uint16_t board_take_lost_samples(void);
/* Milliseconds elapsed since the last call (the 1 ms tick's count). */
uint8_t board_take_ms(void);

void board_motor(float duty); /* 0..1 forward; 0 brakes */
int board_driver_fault(void);
/* A pulse on the driver's nSLEEP, shorter than its sleep time: clears a fault it latched. */
void board_driver_reset(void);
float board_motor_current_A(void); /* mean since the last call */
struct board_encoder {
  int32_t count;
  uint32_t last_edge_us;
  uint16_t edges_a, edges_b; /* each channel's, since the last call */
  uint16_t glitches;         /* impossible transitions since the last call */
};
void board_encoder_read(struct board_encoder *e);

int board_persist_load(struct rig_persist *p); /* 0 when the EEPROM holds nothing valid */
void board_persist_store_begin(const struct rig_persist *p);
void board_persist_store_step(void); /* one byte at a time: the loop never waits for the EEPROM */
void board_new_serial(char serial[RIG_SERIAL_BYTES]);

void board_led(int on);
void board_kick_watchdog(void);
void board_enter_bootloader(void); /* never returns */

#endif
