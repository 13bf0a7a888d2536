#include "ui/panel/round_trip_section.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "playback/audio_devices.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {
namespace {

std::string round_trip_cell(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

std::vector<unsigned> parse_periods(const std::string& text) {
  std::vector<unsigned> periods;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    std::string entry = text.substr(at, comma - at);
    entry.erase(0, entry.find_first_not_of(' '));
    entry.erase(entry.find_last_not_of(' ') + 1);
    const bool digits =
        !entry.empty() && entry.size() <= 6 &&
        std::all_of(entry.begin(), entry.end(), [](char c) { return c >= '0' && c <= '9'; });
    const unsigned long value = digits ? std::stoul(entry) : 0;
    if (value < 1 || value > 65536)
      throw std::invalid_argument("periods: '" + entry +
                                  "' is not a period in frames (1 to 65536; several as 64, 256)");
    periods.push_back(static_cast<unsigned>(value));
    at = comma + 1;
  }
  return periods;
}

RoundTripSection::RoundTripSection() { set_request(request_); }

void RoundTripSection::set_request(const RoundTripRequest& request) {
  request_ = request;
  std::snprintf(input_device_, sizeof input_device_, "%s", request.input_device.c_str());
  std::string periods;
  for (unsigned p : request.periods) periods += (periods.empty() ? "" : ", ") + std::to_string(p);
  std::snprintf(periods_, sizeof periods_, "%s", periods.c_str());
}

void RoundTripSection::start(const DeviceRequest& output) {
  if (job_) return;
  error_.clear();
  try {
    request_.input_device = input_device_;
    request_.periods = parse_periods(periods_);
  } catch (const std::exception& e) {
    error_ = e.what();
    return;
  }
  const RoundTripRequest request = request_;
  measuring_ = request;
  measured_output_ = output;
  started_ = period_started_ = std::chrono::steady_clock::now();
  periods_done_ = 0.0;
  job_ = std::make_unique<BackgroundJob<std::vector<playback::RoundTripResult>>>(
      "measuring the round trip", [output, request](JobControl& control) {
        control.message("opening the device");
        playback::RoundTripSettings s;
        // The device's own rate, as `nibrig latency` takes it: probing is the job's, not the UI's.
        const playback::DeviceChoice choice = playback::choose_device(output.api, output.device);
        s.device = output_settings_of(output, "nibrig-panel-latency");
        s.device.api = choice.api;
        s.device.device = choice.device.name;
        if (choice.device.preferred_sample_rate > 0)
          s.device.sample_rate = choice.device.preferred_sample_rate;
        s.device.input_channel = request.input_channel;
        s.device.input_device = request.input_device;
        s.impulses = request.impulses;
        s.interval_s = request.interval_ms / 1e3;
        control.message("period " + std::to_string(request.periods.front()) + ": playing impulses");
        return playback::measure_round_trips(
            s, request.periods,
            [&control, &request](std::size_t done, std::size_t total,
                                 const playback::RoundTripResult&) {
              control.progress(static_cast<double>(done) / static_cast<double>(total));
              if (done < total)
                control.message("period " + std::to_string(request.periods[done]) +
                                ": playing impulses");
            },
            control.stop_token());
      });
}

double RoundTripSection::shown_progress() const {
  if (!job_) return 0.0;
  const double periods = static_cast<double>(std::max<std::size_t>(1, measuring_.periods.size()));
  const double period_s = std::max(1e-3, measuring_.impulses * measuring_.interval_ms / 1e3);
  const double in_period =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - period_started_).count() / period_s;
  // Within a period the time is an estimate: it stops short of the period's end until reported.
  return std::min(1.0, periods_done_ + std::min(in_period, 0.95) / periods);
}

std::string RoundTripSection::hint() const {
  const bool none_found = std::any_of(results_.begin(), results_.end(),
                                      [](const playback::RoundTripResult& r) { return r.stats.found == 0; });
  if (!none_found) return {};
  const std::string input = measuring_.input_device.empty() ? "the output's own device" : measuring_.input_device;
  std::string hint = "No impulse came back: nothing played on the output reached input channel " +
                     std::to_string(measuring_.input_channel) + " of " + input +
                     ". Connect the output to that input (a loopback cable, or the actuator's accelerometer)";
  if (measured_output_.api == "jack")
    hint += "; a JACK server on its dummy driver returns nothing (jackd -L adds a loopback device, or "
            "connect the ports with jack_connect)";
  return hint + ".";
}

void RoundTripSection::poll() {
  if (job_ && job_->progress() > periods_done_) {
    periods_done_ = job_->progress();
    period_started_ = std::chrono::steady_clock::now();
  }
  if (!job_ || !job_->done()) return;
  if (auto results = job_->take_result()) results_ = std::move(*results);
  error_ = job_->error();
  job_.reset();
}

void RoundTripSection::draw(const DeviceRequest& output) {
  poll();
  section("Round trip (output to input, measured)");
  ImGui::TextWrapped(
      "Plays impulses on the output above (through the actuator and its accelerometer, or a "
      "loopback cable) and finds each in the input by its correlation with the pulse; impulses "
      "not found are counted, not averaged in. No input device: the output's. Several periods: "
      "64, 256.");
  ImGui::InputText(kWidestLabel, input_device_, sizeof input_device_);
  int channel = static_cast<int>(request_.input_channel);
  if (ImGui::InputInt("input channel", &channel))
    request_.input_channel = static_cast<unsigned>(std::max(1, channel));
  ImGui::InputText("periods (frames)", periods_, sizeof periods_);
  if (ImGui::InputInt("impulses per period", &request_.impulses))
    request_.impulses = std::clamp(request_.impulses, 1, 100000);
  if (job_) {
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    const double total_s = measuring_.impulses * measuring_.interval_ms / 1e3 * static_cast<double>(measuring_.periods.size());
    char label[160];
    std::snprintf(label, sizeof label, "%s (%.0f of about %.0f s)", job_->message().c_str(), elapsed_s, total_s);
    if (progress_with_cancel("round-trip", static_cast<float>(shown_progress()), label))
      job_->cancel();
    measure_button_.reset();
  } else {
    if (ImGui::Button("Measure the round trip")) start(output);
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    measure_button_ = ImVec2{0.5f * (min.x + max.x), 0.5f * (min.y + max.y)};
  }
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
  if (const std::string why = hint(); !why.empty() && !job_)
    ImGui::TextColored({1.0f, 0.75f, 0.3f, 1.0f}, "%s", why.c_str());
  draw_table();
}

void RoundTripSection::draw_table() {
  shown_rows_.clear();
  if (results_.empty()) return;
  static constexpr const char* kHeads[] = {
      "device", "period", "found", "mean ms", "sd ms", "worst ms", "frames: mean, worst", "xruns"};
  constexpr int columns = static_cast<int>(std::size(kHeads));
  if (!ImGui::BeginTable("round-trip", columns,
                         ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp))
    return;
  for (const char* head : kHeads) ImGui::TableSetupColumn(head);
  ImGui::TableHeadersRow();
  for (const auto& r : results_) {
    const std::string input =
        r.stream.input_device.empty() || r.stream.input_device == r.stream.device
            ? ""
            : " -> " + r.stream.input_device;
    std::vector<std::string> row{
        r.stream.api + " '" + r.stream.device + "'" + input, std::to_string(r.stream.period_frames),
        std::to_string(r.stats.found) + "/" + std::to_string(r.stats.played)};
    // Nothing found leaves no round trip: a dash, where a 0 would read as one.
    for (double ms : {r.mean_ms, r.stddev_ms, r.worst_ms})
      row.push_back(r.stats.found > 0 ? round_trip_cell("%.3f", ms) : "-");
    row.push_back(r.stats.found > 0 ? round_trip_cell("%.1f", r.stats.mean_samples) + ", " +
                                          std::to_string(r.stats.worst_samples)
                                    : "-");
    row.push_back(std::to_string(r.xruns));
    ImGui::TableNextRow();
    for (const auto& cell : row) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(cell.c_str());
    }
    shown_rows_.push_back(std::move(row));
  }
  ImGui::EndTable();
}

}  // namespace nibrig::ui::panel
