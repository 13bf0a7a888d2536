// The reference rig controller's board with its firmware running: simavr's ATmega32U4 executes the
// ELF that rig/firmware builds, and this object is the world around the chip (rig/HARDWARE.md):
// the gearmotor and turntable driven by the PWM pin through the H-bridge, the encoder's quadrature
// edges from the turntable's angle, the motor current into the ADC, and the two load cells' amplified
// bridge voltages from a force the test sets or the contact's mu*N. Its USB port is driven as a host
// controller would: control transfers in stages, bulk IN packet by packet. Not thread-safe: one
// thread runs the simulation and talks to the port.
#pragma once

#include <simavr/sim_avr.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nibrig::rig::usb::testing {

// The turntable's mechanics and electrics reflected to the output shaft: a Pololu 37D 70:1 12 V
// gearmotor (stall 5.5 A and 2.65 N m, no load 150 rpm at 0.2 A) turning a disc, the tip 60 mm out.
struct TurntablePhysics {
  double supply_V = 12.0;
  double winding_ohm = 12.0 / 5.5;
  double torque_per_A = 2.65 / 5.5;
  double volts_per_rad_s = 0.736;  // (12 V - 0.2 A * R) / 15.7 rad/s
  double friction_Nm = 0.096;      // 0.2 A at no load
  double inertia_kg_m2 = 0.009;    // the rotor through the gearbox dominates the disc
  double track_radius_m = 0.060;
  double counts_per_rev = 4480.0;  // 64 counts a motor turn, times 70
  // A real encoder's edges sit off their even places, in counts: channel B's phase against A, and
  // A's duty cycle (its falling edge). 0: a perfect encoder.
  double encoder_phase_error = 0.0;
  double encoder_duty_error = 0.0;
  double current_V_per_A = 1.65;   // DRV8876 IPROPI, 1100 uA/A into 1.5 kOhm
  // The driver's current regulation: above ITRIP = VREF / (1100 uA/A x 1.5 kOhm) it chops the drive
  // (3.3 V: 2.0 A); a short beyond its over-current protection latches it off, nFAULT low, until a
  // pulse on nSLEEP.
  double itrip_A = 2.0;
  double ocp_A = 5.0;
  // Builders' wiring: encoder A and B swapped against the motor's leads, or the leads swapped.
  bool encoder_reversed = false;
  bool motor_leads_reversed = false;
  double amplifier_V_per_N = 0.255;
  double amplifier_zero_V = 2.5;  // the amplifier's reference (HARDWARE.md)
};

// One run of the frame interrupt: the cycle its compare match was due (the frame's nominal sampling
// instant) and the cycle the chip entered it.
struct FrameInterrupt {
  std::uint64_t due_cycle = 0;
  std::uint64_t entry_cycle = 0;
};

struct ControlOutcome {
  int status = 0;  // 0, or -EPIPE for a STALL
  std::vector<std::uint8_t> in;
};

class SimulatedBoard {
 public:
  // Loads the ELF and powers the board up with `eeprom` (empty: erased, as a new chip).
  explicit SimulatedBoard(const std::string& elf, const std::vector<std::uint8_t>& eeprom = {},
                          TurntablePhysics physics = {});
  ~SimulatedBoard();
  SimulatedBoard(const SimulatedBoard&) = delete;
  SimulatedBoard& operator=(const SimulatedBoard&) = delete;

  // Runs the chip for `us` of simulated time (also: until `cycle` is reached).
  void run_us(double us);
  void run_to_cycle(std::uint64_t cycle);
  std::uint64_t cycle() const { return avr_->cycle; }
  double sim_us() const { return static_cast<double>(avr_->cycle) / 16.0; }
  // The firmware's own clock (timer 3) at the current instant, and at a simulated instant.
  std::uint64_t device_us() const;
  std::uint64_t device_us_at_cycle(std::uint64_t cycle) const;
  std::uint64_t cycle_at_device_us(std::uint64_t device_us) const;
  // The device time of the next frame the firmware will sample.
  std::uint64_t next_frame_device_us() const;
  // The cycle at which the device clock read 0: device time t us is this plus 16 t cycles.
  std::uint64_t clock_start_cycle() const;
  // Every frame interrupt from now on, for the sampling instant's jitter.
  void record_frame_interrupts();
  // The ADC's conversions (its interrupt's entries) from now on.
  void count_adc_conversions();
  std::uint64_t adc_conversions() const { return adc_conversions_; }
  const std::vector<FrameInterrupt>& frame_interrupts() const { return frame_interrupts_; }

  // The world around the chip.
  void set_normal_force(double newtons) { normal_N_ = newtons; }
  void set_friction(double mu) { mu_ = mu; }
  // A force along the track on the tool at rest (a weight over a pulley), added to the contact's.
  void set_tangential_pull(double newtons) { pull_N_ = newtons; }
  // Extra normal force over the frame period that ends at device time `frame_end_us`: the frame
  // sampled then carries all of it, no other frame any of it.
  void pulse_force(std::uint64_t frame_end_us, double extra_N);
  // Faults of the world: the turntable held still (a jammed disc), the encoder's cable pulled (its
  // pins stay where they were).
  void jam(bool held) { jammed_ = held; }
  void disconnect_encoder(bool disconnected) { encoder_disconnected_ = disconnected; }
  // One encoder channel's wire off (0: A, 1: B): its pin stays where it was; -1 puts it back.
  void lose_encoder_channel(int channel) { lost_channel_ = channel; }
  // The motor's 12 V cut (the emergency stop pressed, the fuse blown): the bridge has no supply,
  // its current mirror reads nothing and the motor coasts.
  void set_motor_supply(bool on) { supply_on_ = on; }
  // The disc's hub loose on its shaft: it carries at most this torque (N m) between the motor and
  // the disc; below 0 it holds whatever the torque.
  void set_hub_slip_torque(double newton_metres);
  // The motor's leads shorted together: the driver's over-current protection trips and latches.
  void short_motor_leads(bool shorted) { leads_shorted_ = shorted; }
  bool driver_latched() const { return ocp_latched_; }
  // The chip reset by a brown-out of its own supply (its brown-out detector's flag set), as it comes
  // back: the firmware starts again from reset, and the host must enumerate it anew.
  void brown_out();
  // Current the motor's sense resistor carries beyond the motor's own (a winding shorting, a
  // binding gearbox), until set back to 0.
  void add_motor_current(double amps) { extra_current_A_ = amps; }
  double surface_speed_m_s() const { return disc_omega() * physics_.track_radius_m; }
  double duty() const { return duty_; }
  double motor_current_A() const { return current_A_; }
  double sensed_current_A() const { return sensed_A_; }
  const TurntablePhysics& physics() const { return physics_; }

  // USB, as the host controller: reset and enumerate (returns the device and configuration
  // descriptors); control transfers stepwise (begin, then step until an outcome) or whole.
  std::vector<std::uint8_t> enumerate(int address);
  void begin_control(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& out,
                     std::size_t in_capacity);
  bool control_busy() const { return stage_ != Stage::kIdle; }
  // The stage the transfer in progress waits in: the host's next transaction.
  enum class Stage { kIdle, kDataIn, kDataOut, kStatusIn, kStatusOut };
  Stage control_stage() const { return stage_; }
  std::optional<ControlOutcome> step_control();
  ControlOutcome control(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& out = {},
                         std::size_t in_capacity = 0);
  // One USB packet from a bulk IN endpoint, or nothing (NAK).
  std::optional<std::vector<std::uint8_t>> bulk_in_packet(std::uint8_t endpoint);

  // The stack, sampled after every instruction from now on (a few times slower to run): the main
  // loop's deepest, and the deepest any interrupt went below the pointer it interrupted.
  struct StackUse {
    std::size_t static_bytes = 0;     // .data, .bss and .noinit: below the stack
    std::size_t main_bytes = 0;
    std::size_t interrupt_bytes = 0;
  };
  void watch_stack();
  const StackUse& stack_use() const { return stack_; }

  // Memory: a firmware variable by its ELF symbol, and the EEPROM.
  std::vector<std::uint8_t> read_symbol(const std::string& name, std::size_t size) const;
  std::vector<std::uint8_t> eeprom() const;
  // One byte of the data space (registers and RAM) as it lies there now.
  std::uint8_t data(std::uint16_t address) const { return avr_->data[address]; }

 private:
  static avr_cycle_count_t on_physics(avr_t* avr, avr_cycle_count_t when, void* self);
  static void on_frame_interrupt(avr_irq_t* irq, std::uint32_t value, void* self);
  static void on_adc_interrupt(avr_irq_t* irq, std::uint32_t value, void* self);
  void step_physics(double dt_s);
  void connect_world();
  void sample_stack();
  std::uint16_t stack_pointer() const;  // the world's pins, interrupts' modes and the physics' timer, after a reset
  void step_turntable(double drive_Nm, double dt_s);
  void step_encoder();
  double disc_omega() const { return hub_slip_Nm_ < 0.0 ? omega_ : disc_omega_; }
  static void on_sleep_pin(avr_irq_t* irq, std::uint32_t value, void* self);
  void set_pin(char port, int pin, bool high);
  std::uint16_t reg16(std::uint16_t low_address) const;
  std::uint8_t read_io(std::uint16_t address) const;
  std::uint64_t next_frame_ticks() const;
  bool setup_unread() const;

  TurntablePhysics physics_;
  avr_t* avr_ = nullptr;
  std::vector<std::pair<std::string, std::uint32_t>> symbols_;
  std::uint32_t clock_overflows_address_ = 0;
  std::uint32_t next_frame_address_ = 0;
  std::uint32_t frame_period_address_ = 0;
  avr_irq_t* adc_irq_ = nullptr;

  double normal_N_ = 2.2;  // the paper's load
  double mu_ = 0.3;
  double pull_N_ = 0.0;
  std::optional<std::pair<std::uint64_t, double>> pulse_;  // frame end, extra newtons
  double omega_ = 0.0, theta_ = 0.0, duty_ = 0.0, current_A_ = 0.0;
  long long encoder_count_ = 0;
  std::array<bool, 2> encoder_pins_{};
  bool jammed_ = false, encoder_disconnected_ = false;
  int lost_channel_ = -1;
  bool supply_on_ = true, leads_shorted_ = false, ocp_latched_ = false;
  double hub_slip_Nm_ = -1.0, disc_omega_ = 0.0;
  double extra_current_A_ = 0.0;
  double sensed_A_ = 0.0;  // what the driver's current mirror reads
  bool recording_interrupts_ = false;
  bool counting_conversions_ = false;
  std::uint64_t adc_conversions_ = 0;
  std::vector<FrameInterrupt> frame_interrupts_;
  mutable std::optional<std::uint64_t> clock_start_cycle_;

  bool watching_stack_ = false, in_interrupt_ = false;
  std::uint16_t last_main_sp_ = 0, interrupt_entry_sp_ = 0, interrupt_low_sp_ = 0;
  StackUse stack_;

  Stage stage_ = Stage::kIdle;
  std::array<std::uint8_t, 8> setup_{};
  std::vector<std::uint8_t> out_, in_;
  std::size_t in_capacity_ = 0, out_sent_ = 0;
  int outcome_ = 0;
};

}  // namespace nibrig::rig::usb::testing
