#include "board.h"

#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/wdt.h>
#include <util/atomic.h>
#include <util/delay.h>

#include <string.h>

/* Timer 3 counts at 2 MHz (16 MHz / 8): the device clock is its count, extended by overflows. */
#define TICKS_PER_US 2u
#define PWM_TOP 799u /* 16 MHz / 800: 20 kHz, above hearing */
/* IPROPI of the DRV8876 (1100 uA/A) into 1.5 kOhm, read against 5 V by 1024 counts. */
#define CURRENT_COUNTS_PER_A (1.1e-3f * 1500.0f * 1024.0f / 5.0f)
#define SAMPLE_RING 8u

static volatile uint32_t clock_overflows;
static uint64_t next_frame_ticks; /* the frame interrupt's own */
static volatile uint16_t frame_period_ticks = 2000u;
static volatile uint8_t ms_ticks;

static struct board_sample samples[SAMPLE_RING];
static volatile uint8_t sample_head, sample_tail;
static volatile uint16_t samples_lost;

/* The ADC visits normal, tangential, normal, tangential, current, and again. */
static const uint8_t adc_sequence[5] PROGMEM = {7, 6, 7, 6, 4};
static uint8_t adc_step;
static volatile uint32_t force_sum[2];
static volatile uint8_t force_conversions[2];
static volatile uint32_t current_sum;
static volatile uint16_t current_conversions;

static volatile int32_t encoder_count;
static volatile uint32_t encoder_edge_us;
static volatile uint16_t encoder_edges[2], encoder_glitches;
static uint8_t encoder_state;

/* The chip's reset flags, kept before they are cleared: .noinit, as .init4 clears .bss after this. */
static uint8_t reset_flags __attribute__((section(".noinit")));

/* Stops the watchdog a reset left running before anything else runs. */
void board_early(void) __attribute__((naked, used, section(".init3")));
void board_early(void) {
  reset_flags = MCUSR;
  MCUSR = 0;
  wdt_disable();
}

uint8_t board_reset_cause(void) {
  /* A brown-out also sets the power-on flag when the supply fell far enough: the brown-out is the news. */
  if (reset_flags & (1 << BORF)) return RIG_RESET_BROWN_OUT;
  if (reset_flags & (1 << WDRF)) return RIG_RESET_WATCHDOG;
  if (reset_flags & (1 << PORF)) return RIG_RESET_POWER_ON;
  if (reset_flags & (1 << EXTRF)) return RIG_RESET_EXTERNAL;
  return RIG_RESET_POWER_ON;
}

static uint64_t ticks_now(void) {
  uint32_t high;
  uint16_t low;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    high = clock_overflows;
    low = TCNT3;
    if ((TIFR3 & (1 << TOV3)) && low < 0x8000u) ++high; /* the overflow is pending */
  }
  return ((uint64_t)high << 16) | low;
}

uint64_t board_clock_us(void) { return ticks_now() / TICKS_PER_US; }

ISR(TIMER3_OVF_vect) { ++clock_overflows; }

/* A frame: capture the ADC's sums of the period and schedule the next. */
ISR(TIMER3_COMPA_vect) {
  const uint64_t t = next_frame_ticks;
  next_frame_ticks += frame_period_ticks;
  OCR3A = (uint16_t)next_frame_ticks;
  const uint8_t next = (uint8_t)((sample_head + 1u) % SAMPLE_RING);
  if (next == sample_tail) {
    ++samples_lost;
  } else {
    struct board_sample *s = &samples[sample_head];
    s->t_us = t / TICKS_PER_US;
    for (uint8_t c = 0; c < 2; ++c) {
      s->force_sum[c] = force_sum[c];
      s->conversions[c] = force_conversions[c];
    }
    sample_head = next;
  }
  force_sum[0] = force_sum[1] = 0;
  force_conversions[0] = force_conversions[1] = 0;
}

ISR(TIMER3_COMPB_vect) {
  OCR3B += 2000u; /* 1 ms */
  ++ms_ticks;
}

ISR(ADC_vect) {
  const uint16_t value = ADC;
  const uint8_t channel = pgm_read_byte(&adc_sequence[adc_step]);
  if (channel == 4) {
    current_sum += value;
    ++current_conversions;
  } else {
    const uint8_t c = channel == 7 ? 0 : 1;
    force_sum[c] += value;
    ++force_conversions[c];
  }
  if (++adc_step == sizeof adc_sequence) adc_step = 0; /* no division in an interrupt */
  /* ADC4..7 sit below MUX5; AVCC reference. */
  ADMUX = (uint8_t)((1 << REFS0) | pgm_read_byte(&adc_sequence[adc_step]));
  ADCSRA |= (1 << ADSC);
}

/* Both encoder channels' edges: a quadrature step forward or back, or an impossible jump. */
ISR(INT0_vect) {
  const uint8_t now = (uint8_t)(((PIND & 1u) << 1) | ((PIND >> 1) & 1u)); /* A, B */
  const uint8_t was = encoder_state;
  encoder_state = now;
  if (now == was) return;
  /* Forward runs 00 -> 10 -> 11 -> 01 -> 00 (A leads B); index = was * 4 + now. Both bits at
   * once is not a quadrature step: a glitch. */
  static const int8_t step[16] PROGMEM = {0, -1, 1, 0, 1, 0, 0, -1, -1, 0, 0, 1, 0, 1, -1, 0};
  if ((now ^ was) == 3u) {
    ++encoder_glitches;
    return;
  }
  const int8_t d = (int8_t)pgm_read_byte(&step[was * 4u + now]);
  encoder_count += d;
  ++encoder_edges[(now ^ was) == 2u ? 0 : 1]; /* A is the high bit */
  encoder_edge_us = (uint32_t)(ticks_now() / TICKS_PER_US);
}
ISR(INT1_vect, ISR_ALIASOF(INT0_vect));

void board_init(void) {
  wdt_enable(WDTO_1S); /* a hung firmware resets, and the motor stops with it */
  /* Motor: PB5 OC1A PWM, PB4 direction, PB6 nSLEEP; PD4 nFAULT with pull-up; PC7 LED. */
  DDRB |= (1 << PB5) | (1 << PB4) | (1 << PB6);
  PORTB &= (uint8_t) ~((1 << PB5) | (1 << PB4));
  PORTB |= (1 << PB6);
  DDRD &= (uint8_t) ~((1 << PD4) | (1 << PD0) | (1 << PD1));
  PORTD |= (1 << PD4);
  DDRC |= (1 << PC7);
  /* Timer 1: fast PWM, TOP = ICR1 (mode 14), no prescaler. */
  ICR1 = PWM_TOP;
  OCR1A = 0;
  TCCR1A = (1 << WGM11);
  TCCR1B = (1 << WGM13) | (1 << WGM12) | (1 << CS10);
  /* Timer 3: normal mode, 2 MHz; compare A the frames, compare B the millisecond. */
  TCCR3A = 0;
  TCCR3B = (1 << CS31);
  next_frame_ticks = TCNT3 + (uint64_t)frame_period_ticks;
  OCR3A = (uint16_t)next_frame_ticks;
  OCR3B = (uint16_t)(TCNT3 + 2000u);
  TIMSK3 = (1 << TOIE3) | (1 << OCIE3A) | (1 << OCIE3B);
  /* Encoder: INT0 and INT1 on any edge. */
  encoder_state = (uint8_t)(((PIND & 1u) << 1) | ((PIND >> 1) & 1u));
  EICRA = (1 << ISC00) | (1 << ISC10);
  EIMSK = (1 << INT0) | (1 << INT1);
  /* ADC: AVCC reference, 125 kHz ADC clock (16 MHz / 128, within the 200 kHz its 10 bits need):
   * 104 us a conversion, about four of each force channel a frame at 1 kHz. */
  DIDR0 = (1 << ADC7D) | (1 << ADC6D) | (1 << ADC4D);
  ADMUX = (uint8_t)((1 << REFS0) | pgm_read_byte(&adc_sequence[0]));
  ADCSRA = (1 << ADEN) | (1 << ADIE) | (1 << ADPS2) | (1 << ADPS1) | (1 << ADPS0) | (1 << ADSC);
}

void board_set_frame_rate(uint16_t hz) {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { frame_period_ticks = (uint16_t)(2000000ul / hz); }
}

int board_take_sample(struct board_sample *s) {
  if (sample_tail == sample_head) return 0;
  *s = samples[sample_tail];
  sample_tail = (uint8_t)((sample_tail + 1u) % SAMPLE_RING);
  return 1;
}

uint16_t board_take_lost_samples(void) {
  uint16_t n;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    n = samples_lost;
    samples_lost = 0;
  }
  return n;
}

uint8_t board_take_ms(void) {
  uint8_t n;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    n = ms_ticks;
    ms_ticks = 0;
  }
  return n;
}

void board_motor(float duty) {
  if (!(duty > 0.0f)) {
    TCCR1A &= (uint8_t) ~(1 << COM1A1); /* EN low: the bridge brakes */
    PORTB &= (uint8_t) ~(1 << PB5);
    return;
  }
  if (duty > 1.0f) duty = 1.0f;
  OCR1A = (uint16_t)(duty * (float)PWM_TOP + 0.5f);
  TCCR1A |= (1 << COM1A1);
}

int board_driver_fault(void) { return !(PIND & (1 << PD4)); }

void board_driver_reset(void) {
  PORTB &= (uint8_t) ~(1 << PB6);
  _delay_us(20);
  PORTB |= (1 << PB6);
}

float board_motor_current_A(void) {
  uint32_t sum;
  uint16_t n;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    sum = current_sum;
    n = current_conversions;
    current_sum = 0;
    current_conversions = 0;
  }
  return n == 0 ? 0.0f : (float)sum / (float)n / CURRENT_COUNTS_PER_A;
}

void board_encoder_read(struct board_encoder *e) {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    e->count = encoder_count;
    e->last_edge_us = encoder_edge_us;
    e->edges_a = encoder_edges[0];
    e->edges_b = encoder_edges[1];
    e->glitches = encoder_glitches;
    encoder_edges[0] = encoder_edges[1] = 0;
    encoder_glitches = 0;
  }
}

/* EEPROM: a key, then the persistent state as it lies in RAM. */
#define PERSIST_KEY 0x4E31u
static uint8_t *const persist_eeprom = (uint8_t *)2;
static struct rig_persist persist_copy;
static uint8_t persist_next = sizeof(struct rig_persist);

int board_persist_load(struct rig_persist *p) {
  if (eeprom_read_word((const uint16_t *)0) != PERSIST_KEY) return 0;
  eeprom_read_block(p, persist_eeprom, sizeof *p);
  return rig_persist_valid(p);
}

void board_persist_store_begin(const struct rig_persist *p) {
  persist_copy = *p;
  persist_next = 0;
}

void board_persist_store_step(void) {
  if (persist_next > sizeof persist_copy || !eeprom_is_ready()) return;
  if (persist_next == sizeof persist_copy) {
    eeprom_update_word((uint16_t *)0, PERSIST_KEY); /* last: a torn write leaves no valid key */
  } else {
    eeprom_update_byte(persist_eeprom + persist_next, ((const uint8_t *)&persist_copy)[persist_next]);
  }
  ++persist_next;
}

/* A fresh board's serial: the timer's phase at the ADC's first conversions differs board to board. */
void board_new_serial(char serial[RIG_SERIAL_BYTES]) {
  static const char hex[] PROGMEM = "0123456789ABCDEF";
  uint16_t seed = 0;
  for (uint8_t i = 0; i < 16; ++i) {
    seed = (uint16_t)((seed << 1) ^ TCNT3 ^ ADC ^ (seed >> 15));
    _delay_us(37);
  }
  memset(serial, 0, RIG_SERIAL_BYTES);
  memcpy(serial, "NIB-", 4);
  for (uint8_t i = 0; i < 4; ++i) serial[4 + i] = (char)pgm_read_byte(&hex[(seed >> (12 - 4 * i)) & 0xFu]);
}

void board_led(int on) {
  if (on) {
    PORTC |= (1 << PC7);
  } else {
    PORTC &= (uint8_t) ~(1 << PC7);
  }
}

void board_kick_watchdog(void) { wdt_reset(); }

/* Caterina (the Leonardo's and Pro Micro's bootloader) stays in the bootloader after a watchdog
 * reset when it finds 0x7777 at 0x0800 (older builds) or at the top of RAM (newer ones). */
void board_enter_bootloader(void) {
  cli();
  board_motor(0.0f);
  UDCON |= (1 << DETACH);
  USBCON &= (uint8_t) ~(1 << USBE);
  _delay_ms(50);
  *(volatile uint16_t *)0x0800 = 0x7777u;
  *(volatile uint16_t *)(RAMEND - 1) = 0x7777u;
  wdt_enable(WDTO_15MS);
  for (;;) {
  }
}
