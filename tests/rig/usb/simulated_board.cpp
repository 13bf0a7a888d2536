#include "tests/rig/usb/simulated_board.hpp"

#include <simavr/avr_adc.h>
#include <simavr/avr_eeprom.h>
#include <simavr/avr_extint.h>
#include <simavr/avr_ioport.h>
#include <simavr/avr_usb.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_interrupts.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace nibrig::rig::usb::testing {
namespace {

constexpr std::uint32_t kFrequency = 16'000'000;
constexpr avr_cycle_count_t kPhysicsCycles = 800;  // 50 us: 20 steps a frame at 1 kHz
constexpr std::uint32_t kDataSpace = 0x800000;      // avr-gcc's offset of RAM addresses in the ELF
// ATmega32U4 registers (data-space addresses, avr/iom32u4.h).
constexpr std::uint16_t kUeintx = 0xE8, kUenum = 0xE9;
constexpr std::uint16_t kTccr1a = 0x80, kIcr1 = 0x86, kOcr1a = 0x88, kTccr3b = 0x91, kTcnt3 = 0x94, kPortb = 0x25;
constexpr double kAvccMillivolts = 5000.0;
constexpr std::uint8_t kTimer3CompareAVector = 32;  // TIMER3_COMPA_vect_num, the frame interrupt
constexpr std::uint8_t kAdcVector = 29;              // ADC_vect_num: one conversion done
constexpr std::uint16_t kSpl = 0x5D;                 // the stack pointer's low byte; SPH follows
constexpr std::uint16_t kRamEnd = 0x0AFF;            // the stack starts here and grows down


// Friction opposes motion and never reverses it; a body at rest stays there while the torque on it
// is within the friction.
double sim_board_spin(double omega, double torque, double friction, double inertia, double dt_s) {
  if (omega == 0.0 && std::abs(torque) <= friction) return 0.0;
  const double after = omega + (torque - std::copysign(friction, omega != 0.0 ? omega : torque)) / inertia * dt_s;
  return omega != 0.0 && std::signbit(omega) != std::signbit(after) ? 0.0 : after;
}

}  // namespace

SimulatedBoard::SimulatedBoard(const std::string& elf, const std::vector<std::uint8_t>& eeprom,
                               TurntablePhysics physics)
    : physics_(physics) {
  // elf_firmware_t's layout follows ELF_SYMBOLS, which the header and the library agree on (1).
  auto firmware = std::make_unique<elf_firmware_t>();
  std::memset(firmware.get(), 0, sizeof(elf_firmware_t));
  if (elf_read_firmware(elf.c_str(), firmware.get()) != 0) {
    throw std::runtime_error("simavr cannot read the firmware " + elf);
  }
  for (std::uint32_t i = 0; i < firmware->symbolcount; ++i) {
    symbols_.emplace_back(firmware->symbol[i]->symbol, firmware->symbol[i]->addr);
  }
  avr_ = avr_make_mcu_by_name("atmega32u4");
  if (avr_ == nullptr) throw std::runtime_error("simavr has no atmega32u4 core");
  avr_init(avr_);
  avr_->log = LOG_NONE;
  avr_->frequency = kFrequency;
  avr_->vcc = avr_->avcc = avr_->aref = static_cast<std::uint32_t>(kAvccMillivolts);
  avr_load_firmware(avr_, firmware.get());
  // Copied into the chip's flash and EEPROM by now.
  std::free(firmware->flash);
  std::free(firmware->eeprom);
  if (!eeprom.empty()) {
    avr_eeprom_desc_t desc{const_cast<std::uint8_t*>(eeprom.data()), 0, static_cast<std::uint32_t>(eeprom.size())};
    avr_ioctl(avr_, AVR_IOCTL_EEPROM_SET, &desc);
  }
  for (const auto& [name, address] : symbols_) {
    if (name == "_end") stack_.static_bytes = address - kDataSpace - 0x100;  // RAM starts at 0x100
    if (name == "clock_overflows") clock_overflows_address_ = address - kDataSpace;
    if (name == "next_frame_ticks") next_frame_address_ = address - kDataSpace;
    if (name == "frame_period_ticks") frame_period_address_ = address - kDataSpace;
  }
  if (clock_overflows_address_ == 0 || next_frame_address_ == 0 || frame_period_address_ == 0) {
    throw std::runtime_error(elf + " is not the rig controller's firmware (no device clock symbols)");
  }
  adc_irq_ = avr_io_getirq(avr_, AVR_IOCTL_ADC_GETIRQ, 0);
  avr_irq_register_notify(avr_io_getirq(avr_, AVR_IOCTL_IOPORT_GETIRQ('B'), 6), &SimulatedBoard::on_sleep_pin, this);
  connect_world();
}

SimulatedBoard::~SimulatedBoard() {
  avr_terminate(avr_);
  std::free(avr_);
}

void SimulatedBoard::run_to_cycle(std::uint64_t cycle) {
  while (avr_->cycle < cycle) {
    const int state = avr_run(avr_);
    if (state == cpu_Done || state == cpu_Crashed) throw std::runtime_error("the simulated firmware stopped");
    if (watching_stack_) sample_stack();
  }
}

void SimulatedBoard::watch_stack() {
  watching_stack_ = true;
  last_main_sp_ = stack_pointer();
}

std::uint16_t SimulatedBoard::stack_pointer() const {
  return static_cast<std::uint16_t>(avr_->data[kSpl] | (avr_->data[kSpl + 1] << 8));
}

// After every instruction: the main loop's lowest stack pointer, and each interrupt's depth below the
// pointer it found (its return address, the registers it saves, its locals). Interrupts here do not
// nest (no handler enables them), so the worst is the sum of the two deepest.
void SimulatedBoard::sample_stack() {
  const std::uint16_t sp = stack_pointer();
  if (avr_->interrupts.running_ptr == 0) {
    if (in_interrupt_) {
      in_interrupt_ = false;
      stack_.interrupt_bytes = std::max<std::size_t>(stack_.interrupt_bytes, interrupt_entry_sp_ - interrupt_low_sp_);
    }
    last_main_sp_ = sp;
    stack_.main_bytes = std::max<std::size_t>(stack_.main_bytes, kRamEnd - sp);
  } else {
    if (!in_interrupt_) {
      in_interrupt_ = true;
      interrupt_entry_sp_ = last_main_sp_;
      interrupt_low_sp_ = sp;
    }
    interrupt_low_sp_ = std::min(interrupt_low_sp_, sp);
  }
}

void SimulatedBoard::run_us(double us) { run_to_cycle(avr_->cycle + static_cast<std::uint64_t>(us * 16.0)); }

std::uint16_t SimulatedBoard::reg16(std::uint16_t low_address) const {
  return static_cast<std::uint16_t>(avr_->data[low_address] | (avr_->data[low_address + 1] << 8));
}

// An I/O register as the firmware would read it: simavr computes some (a timer's count) on access.
std::uint8_t SimulatedBoard::read_io(std::uint16_t address) const {
  const auto& io = avr_->io[AVR_DATA_TO_IO(address)];
  return io.r.c != nullptr ? io.r.c(avr_, address, io.r.param) : avr_->data[address];
}

// Timer 3 counts cycles / 8 from where it started; the firmware's clock is its count / 2. Kept once
// the timer runs and its count is far from an overflow the firmware has not yet counted; simavr
// computes the count from the start's cycle, so this is that cycle to within the prescaler's 8.
std::uint64_t SimulatedBoard::clock_start_cycle() const {
  if (clock_start_cycle_) return *clock_start_cycle_;
  std::uint32_t overflows = 0;
  std::memcpy(&overflows, &avr_->data[clock_overflows_address_], sizeof overflows);
  const std::uint8_t low = read_io(kTcnt3);  // first: reading the low byte latches the high one
  const std::uint16_t count = static_cast<std::uint16_t>(low | (read_io(kTcnt3 + 1) << 8));
  const std::uint64_t ticks = (static_cast<std::uint64_t>(overflows) << 16) | count;
  const std::uint64_t started = avr_->cycle - ticks * 8;
  if (avr_->data[kTccr3b] != 0 && count > 0x0100 && count < 0xFF00) clock_start_cycle_ = started;
  return started;
}

std::uint64_t SimulatedBoard::device_us_at_cycle(std::uint64_t cycle) const {
  const std::uint64_t started = clock_start_cycle();
  return cycle < started ? 0 : (cycle - started) / 16;
}

std::uint64_t SimulatedBoard::device_us() const { return device_us_at_cycle(avr_->cycle); }

std::uint64_t SimulatedBoard::cycle_at_device_us(std::uint64_t device_us) const {
  return avr_->cycle + (device_us - this->device_us()) * 16;
}

std::uint64_t SimulatedBoard::next_frame_ticks() const {
  std::uint64_t ticks = 0;
  std::memcpy(&ticks, &avr_->data[next_frame_address_], sizeof ticks);  // little-endian, as the AVR's
  return ticks;
}

std::uint64_t SimulatedBoard::next_frame_device_us() const { return next_frame_ticks() / 2; }

void SimulatedBoard::pulse_force(std::uint64_t frame_end_us, double extra_N) {
  pulse_ = std::make_pair(frame_end_us, extra_N);
}

void SimulatedBoard::set_pin(char port, int pin, bool high) {
  avr_irq_t* irq = avr_io_getirq(avr_, AVR_IOCTL_IOPORT_GETIRQ(port), pin);
  avr_raise_irq(irq, high ? 1 : 0);
}

void SimulatedBoard::record_frame_interrupts() {
  if (recording_interrupts_) return;
  recording_interrupts_ = true;
  // simavr raises a vector's "running" IRQ to 1 as the chip enters its handler.
  avr_irq_t* irqs = avr_get_interrupt_irq(avr_, kTimer3CompareAVector);
  avr_irq_register_notify(irqs + AVR_INT_IRQ_RUNNING, &SimulatedBoard::on_frame_interrupt, this);
}

void SimulatedBoard::count_adc_conversions() {
  if (counting_conversions_) return;
  counting_conversions_ = true;
  avr_irq_t* irqs = avr_get_interrupt_irq(avr_, kAdcVector);
  avr_irq_register_notify(irqs + AVR_INT_IRQ_RUNNING, &SimulatedBoard::on_adc_interrupt, this);
}

void SimulatedBoard::on_adc_interrupt(avr_irq_t*, std::uint32_t value, void* self) {
  if (value == 1) ++static_cast<SimulatedBoard*>(self)->adc_conversions_;
}

void SimulatedBoard::on_frame_interrupt(avr_irq_t*, std::uint32_t value, void* self) {
  auto* board = static_cast<SimulatedBoard*>(self);
  if (value != 1) return;
  // On entry the handler has not yet moved next_frame_ticks on: it holds this frame's due tick.
  const std::uint64_t due_tick = board->next_frame_ticks();
  board->frame_interrupts_.push_back({board->clock_start_cycle() + due_tick * 8, board->avr_->cycle});
}

avr_cycle_count_t SimulatedBoard::on_physics(avr_t*, avr_cycle_count_t when, void* self) {
  static_cast<SimulatedBoard*>(self)->step_physics(static_cast<double>(kPhysicsCycles) / kFrequency);
  return when + kPhysicsCycles;
}

void SimulatedBoard::step_physics(double dt_s) {
  const TurntablePhysics& p = physics_;
  // The H-bridge in PH/EN mode: EN (OC1A) high drives, low brakes (both low sides on); asleep, it
  // lets the motor coast, and so it does without its supply or latched off by a fault.
  const bool powered = supply_on_ && !ocp_latched_;
  const bool awake = (avr_->data[kPortb] & (1 << 6)) && powered;
  const bool pwm_on = avr_->data[kTccr1a] & (1 << 7);
  const std::uint16_t top = reg16(kIcr1);
  duty_ = pwm_on && top > 0 ? std::min(1.0, static_cast<double>(reg16(kOcr1a)) / top) : 0.0;
  const double direction = ((avr_->data[kPortb] & (1 << 4)) ? -1.0 : 1.0) * (p.motor_leads_reversed ? -1.0 : 1.0);
  const double volts = direction * duty_ * p.supply_V;
  double motor_A = awake ? (volts - p.volts_per_rad_s * omega_) / p.winding_ohm : 0.0;
  if (awake && leads_shorted_ && duty_ > 0.0) {
    // A short's current passes the protection's threshold within microseconds: latched off.
    ocp_latched_ = true;
    motor_A = 0.0;
  }
  // The current mirror carries the motor's current and whatever else the bridge feeds; above ITRIP
  // the driver chops the drive until it reads ITRIP.
  double sensed = powered ? std::abs(motor_A) + extra_current_A_ : 0.0;
  if (awake && sensed > p.itrip_A && motor_A > 0.0) {
    motor_A = std::min(motor_A, std::max(0.0, p.itrip_A - extra_current_A_));
    sensed = p.itrip_A;
  }
  current_A_ = motor_A;
  sensed_A_ = sensed;
  set_pin('D', 4, !ocp_latched_);  // nFAULT: low while the driver holds a fault
  step_turntable(p.torque_per_A * current_A_, dt_s);
  step_encoder();

  // The analog side: motor current, then the two bridges through their amplifiers.
  avr_irq_t* const adc = adc_irq_;
  auto millivolts = [](double v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0, 5.0) * 1000.0 + 0.5); };
  avr_raise_irq(adc + ADC_IRQ_ADC4, millivolts(sensed_A_ * p.current_V_per_A));
  double normal = normal_N_;
  if (pulse_ && avr_->data[kTccr3b] != 0) {
    // The frame ending at pulse_->first averages the period before it.
    const std::uint64_t now = device_us();
    const std::uint16_t period_ticks = static_cast<std::uint16_t>(avr_->data[frame_period_address_] |
                                                                   (avr_->data[frame_period_address_ + 1] << 8));
    const std::uint64_t start = pulse_->first - period_ticks / 2;
    if (now > start && now <= pulse_->first) normal += pulse_->second;
    if (now > pulse_->first) pulse_.reset();
  }
  const double disc = disc_omega();
  const double tangential = (disc != 0.0 ? std::copysign(mu_ * normal_N_, disc) : 0.0) + pull_N_;
  avr_raise_irq(adc + ADC_IRQ_ADC7, millivolts(p.amplifier_zero_V + normal * p.amplifier_V_per_N));
  avr_raise_irq(adc + ADC_IRQ_ADC6, millivolts(p.amplifier_zero_V + tangential * p.amplifier_V_per_N));
}

// The gearbox's friction acts on the motor's side, the tip's on the disc. A hub that holds makes
// them one body; a loose one carries at most its slip torque, and the disc (a ninth of the inertia:
// the rotor through the gearbox dominates) then runs on its own.
void SimulatedBoard::step_turntable(double drive_Nm, double dt_s) {
  const TurntablePhysics& p = physics_;
  const double contact = mu_ * normal_N_ * p.track_radius_m;
  if (jammed_) {
    omega_ = disc_omega_ = 0.0;
  } else if (hub_slip_Nm_ < 0.0) {
    omega_ = sim_board_spin(omega_, drive_Nm, p.friction_Nm + contact, p.inertia_kg_m2, dt_s);
    disc_omega_ = omega_;
  } else {
    const double disc_inertia = p.inertia_kg_m2 / 9.0, motor_inertia = p.inertia_kg_m2 - disc_inertia;
    double hub = 0.0;
    if (omega_ != disc_omega_) {
      hub = std::copysign(hub_slip_Nm_, omega_ - disc_omega_);
    } else {
      // Turning together: the torque the hub must pass for the disc to keep up with the motor.
      const double together = sim_board_spin(omega_, drive_Nm, p.friction_Nm + contact, p.inertia_kg_m2, dt_s);
      const double needed = disc_inertia * (together - disc_omega_) / dt_s + std::copysign(contact, together);
      hub = std::abs(needed) <= hub_slip_Nm_ ? needed : std::copysign(hub_slip_Nm_, needed);
    }
    const double motor_before = omega_;
    omega_ = sim_board_spin(omega_, drive_Nm - hub, p.friction_Nm, motor_inertia, dt_s);
    disc_omega_ = sim_board_spin(disc_omega_, hub, contact, disc_inertia, dt_s);
    // The faster one cannot overtake the other through the hub's friction within a step.
    if ((motor_before - disc_omega_) * (omega_ - disc_omega_) < 0.0) disc_omega_ = omega_;
  }
  theta_ += omega_ * dt_s;
}

// The encoder on the motor's shaft: A leads B going forward (00, 10, 11, 01). Edge k sits at k
// counts plus its channel's error: A rises at 0 and falls at 2 (its duty), B at 1 and 3 (its
// phase). The count is the last edge passed. Wired with A and B swapped, the chip sees B lead A.
void SimulatedBoard::step_encoder() {
  const TurntablePhysics& p = physics_;
  const double position = theta_ / (2.0 * M_PI) * p.counts_per_rev;
  const double edge_error[4] = {0.0, p.encoder_phase_error, p.encoder_duty_error, p.encoder_phase_error};
  auto count = static_cast<long long>(std::floor(position)) + 1;
  while (static_cast<double>(count) + edge_error[((count % 4) + 4) % 4] > position) --count;
  while (!encoder_disconnected_ && encoder_count_ != count) {
    encoder_count_ += count > encoder_count_ ? 1 : -1;
    static constexpr bool kA[4] = {false, true, true, false};
    static constexpr bool kB[4] = {false, false, true, true};
    const int phase = static_cast<int>(((encoder_count_ % 4) + 4) % 4);
    const bool a = p.encoder_reversed ? kB[phase] : kA[phase];
    const bool b = p.encoder_reversed ? kA[phase] : kB[phase];
    if (lost_channel_ != 0 && encoder_pins_[0] != a) set_pin('D', 0, encoder_pins_[0] = a);
    if (lost_channel_ != 1 && encoder_pins_[1] != b) set_pin('D', 1, encoder_pins_[1] = b);
  }
}

void SimulatedBoard::set_hub_slip_torque(double newton_metres) {
  hub_slip_Nm_ = newton_metres;
  disc_omega_ = omega_;
}

void SimulatedBoard::on_sleep_pin(avr_irq_t*, std::uint32_t value, void* self) {
  if (value == 0) static_cast<SimulatedBoard*>(self)->ocp_latched_ = false;  // nSLEEP's pulse clears the latch
}

void SimulatedBoard::brown_out() {
  avr_reset(avr_);  // clears the data space and simavr's cycle timers: the world's are set up again
  // The brown-out detector's flag (MCUSR bit 2), as the chip leaves reset with it set.
  avr_->data[0x54] |= 1u << 2;
  clock_start_cycle_.reset();
  connect_world();
}

void SimulatedBoard::connect_world() {
  // The encoder's INT0/INT1 run on any edge. simavr keeps raising a low-level interrupt for as long
  // as a pin stays low once it saw the pin fall in that mode (the reset state, before the firmware
  // chose its edges); the encoder's pins rest low, so that would never stop.
  avr_extint_set_strict_lvl_trig(avr_, 0, 0);
  avr_extint_set_strict_lvl_trig(avr_, 1, 0);
  // The driver is awake and well (nFAULT high) unless latched; the encoder's pins where they are.
  set_pin('D', 4, !ocp_latched_);
  set_pin('D', 0, encoder_pins_[0]);
  set_pin('D', 1, encoder_pins_[1]);
  step_physics(0.0);
  avr_cycle_timer_register(avr_, kPhysicsCycles, &SimulatedBoard::on_physics, this);
}

std::vector<std::uint8_t> SimulatedBoard::read_symbol(const std::string& name, std::size_t size) const {
  for (const auto& [symbol, address] : symbols_) {
    if (symbol == name && address >= kDataSpace) {
      const std::uint32_t at = address - kDataSpace;
      return {avr_->data + at, avr_->data + at + size};
    }
  }
  throw std::runtime_error("the firmware has no variable '" + name + "'");
}

std::vector<std::uint8_t> SimulatedBoard::eeprom() const {
  std::vector<std::uint8_t> bytes(1024);
  avr_eeprom_desc_t desc{bytes.data(), 0, static_cast<std::uint32_t>(bytes.size())};
  avr_ioctl(avr_, AVR_IOCTL_EEPROM_GET, &desc);
  if (desc.ee != nullptr && desc.ee != bytes.data()) std::memcpy(bytes.data(), desc.ee, bytes.size());
  return bytes;
}

// --- USB, as the host controller drives it ---

void SimulatedBoard::begin_control(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& out,
                                   std::size_t in_capacity) {
  setup_ = setup;
  out_ = out;
  in_.clear();
  in_capacity_ = in_capacity;
  out_sent_ = 0;
  outcome_ = 0;
  avr_io_usb io{0, 8, setup_.data()};
  avr_ioctl(avr_, AVR_IOCTL_USB_SETUP, &io);
  const bool in = setup_[0] & 0x80;
  const std::size_t length = setup_[6] | (setup_[7] << 8);
  stage_ = in ? (length > 0 ? Stage::kDataIn : Stage::kStatusIn) : (length > 0 ? Stage::kDataOut : Stage::kStatusIn);
}

// One transaction of the transfer in progress; the outcome once its status stage is done.
std::optional<ControlOutcome> SimulatedBoard::step_control() {
  std::uint8_t buffer[64];
  const bool in = setup_[0] & 0x80;
  switch (stage_) {
    case Stage::kIdle: return std::nullopt;
    case Stage::kDataIn: {
      avr_io_usb io{0, sizeof buffer, buffer};
      const int r = avr_ioctl(avr_, AVR_IOCTL_USB_READ, &io);
      if (r == AVR_IOCTL_USB_NAK) return std::nullopt;
      if (r == AVR_IOCTL_USB_STALL) {
        stage_ = Stage::kIdle;
        return ControlOutcome{-EPIPE, {}};
      }
      in_.insert(in_.end(), buffer, buffer + io.sz);
      const std::size_t length = setup_[6] | (setup_[7] << 8);
      if (io.sz < 64 || in_.size() >= length) stage_ = Stage::kStatusOut;
      return std::nullopt;
    }
    case Stage::kDataOut: {
      // A real controller NAKs the data while the SETUP sits unread in the endpoint's bank; simavr
      // would write the data over it. So the data waits until the firmware has taken the SETUP.
      if (out_sent_ == 0 && setup_unread()) return std::nullopt;
      const std::size_t n = std::min<std::size_t>(64, out_.size() - out_sent_);
      std::memcpy(buffer, out_.data() + out_sent_, n);
      avr_io_usb io{0, static_cast<std::uint32_t>(n), buffer};
      const int r = avr_ioctl(avr_, AVR_IOCTL_USB_WRITE, &io);
      if (r == AVR_IOCTL_USB_NAK) return std::nullopt;
      if (r == AVR_IOCTL_USB_STALL) {
        stage_ = Stage::kIdle;
        return ControlOutcome{-EPIPE, {}};
      }
      out_sent_ += n;
      if (out_sent_ >= out_.size()) stage_ = Stage::kStatusIn;
      return std::nullopt;
    }
    case Stage::kStatusIn: {  // after an OUT (or no) data stage: the device's zero-length IN
      avr_io_usb io{0, sizeof buffer, buffer};
      const int r = avr_ioctl(avr_, AVR_IOCTL_USB_READ, &io);
      if (r == AVR_IOCTL_USB_NAK) return std::nullopt;
      stage_ = Stage::kIdle;
      return ControlOutcome{r == AVR_IOCTL_USB_STALL ? -EPIPE : 0, {}};
    }
    case Stage::kStatusOut: {  // after an IN data stage: the host's zero-length OUT
      avr_io_usb io{0, 0, buffer};
      const int r = avr_ioctl(avr_, AVR_IOCTL_USB_WRITE, &io);
      if (r == AVR_IOCTL_USB_NAK) return std::nullopt;
      stage_ = Stage::kIdle;
      if (r == AVR_IOCTL_USB_STALL) return ControlOutcome{-EPIPE, {}};
      if (in_.size() > in_capacity_ && in) in_.resize(in_capacity_);
      return ControlOutcome{0, in_};
    }
  }
  return std::nullopt;
}

// EP0's RXSTPI, read as the firmware would with EP0 selected (its UENUM put back after).
bool SimulatedBoard::setup_unread() const {
  const std::uint8_t selected = avr_->data[kUenum];
  avr_->data[kUenum] = 0;
  const bool unread = read_io(kUeintx) & (1 << 3);
  avr_->data[kUenum] = selected;
  return unread;
}

ControlOutcome SimulatedBoard::control(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& out,
                                       std::size_t in_capacity) {
  begin_control(setup, out, in_capacity);
  // A host gives a control transfer 5 s; simulated time, so this is about the firmware, not the machine.
  const std::uint64_t deadline = avr_->cycle + 5ull * kFrequency;
  while (avr_->cycle < deadline) {
    run_us(20.0);
    if (auto outcome = step_control()) return *outcome;
  }
  stage_ = Stage::kIdle;
  throw std::runtime_error("the simulated firmware did not complete a control transfer in 5 s");
}

std::optional<std::vector<std::uint8_t>> SimulatedBoard::bulk_in_packet(std::uint8_t endpoint) {
  std::uint8_t buffer[64];
  avr_io_usb io{static_cast<std::uint8_t>(endpoint & 0x7F), sizeof buffer, buffer};
  const int r = avr_ioctl(avr_, AVR_IOCTL_USB_READ, &io);
  // simavr answers a NAK on a bulk endpoint as an empty packet: the firmware never sends one.
  if (r != AVR_IOCTL_USB_OK || io.sz == 0) return std::nullopt;
  return std::vector<std::uint8_t>(buffer, buffer + io.sz);
}

std::vector<std::uint8_t> SimulatedBoard::enumerate(int address) {
  // Attached (the firmware cleared DETACH at start-up), then the bus reset and the kernel's requests.
  run_us(20'000.0);
  avr_ioctl(avr_, AVR_IOCTL_USB_RESET, nullptr);
  run_us(1'000.0);
  auto require = [](const ControlOutcome& o, const char* what) {
    if (o.status != 0) throw std::runtime_error(std::string("the simulated firmware refused ") + what);
    return o.in;
  };
  std::vector<std::uint8_t> descriptors = require(control({0x80, 6, 0, 1, 0, 0, 18, 0}, {}, 18), "GET_DESCRIPTOR(device)");
  require(control({0x00, 5, static_cast<std::uint8_t>(address), 0, 0, 0, 0, 0}), "SET_ADDRESS");
  const auto head = require(control({0x80, 6, 0, 2, 0, 0, 9, 0}, {}, 9), "GET_DESCRIPTOR(configuration)");
  if (head.size() < 4) throw std::runtime_error("the simulated firmware's configuration descriptor is short");
  const std::uint8_t total = head[2];
  const auto configuration = require(control({0x80, 6, 0, 2, 0, 0, total, 0}, {}, total), "GET_DESCRIPTOR(configuration)");
  descriptors.insert(descriptors.end(), configuration.begin(), configuration.end());
  require(control({0x00, 9, 1, 0, 0, 0, 0, 0}), "SET_CONFIGURATION");
  return descriptors;
}

}  // namespace nibrig::rig::usb::testing
