#include "ui/panel/rig_view.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "model/design/tool_sound.hpp"
#include "rig/actuator_player.hpp"
#include "rig/comparison_start.hpp"
#include "ui/panel/plot_frame.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace {

// The waterfalls show the comparison's band (SpeedBinnedComparisonSettings: up to 500 Hz, where the
// catalog's spectra end): above it the measured tool has nothing and the difference says nothing.
constexpr double kShownMaxHz = 500.0;
constexpr std::size_t kWaterfallRows = 480;  // 10 s at the analysis's 21 ms per row
constexpr std::size_t kTraceFrames = 1000;   // 10 s of traces at 100 Hz
constexpr float kLowDb = -60.0f, kHighDb = 20.0f;  // peak amplitude re 1 m/s²
constexpr float kDifferenceSpanDb = 20.0f;

std::string timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", std::localtime(&t));
  return text;
}

void input_text(const char* label, std::string& value) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%s", value.c_str());
  if (ImGui::InputText(label, buffer, sizeof buffer)) value = buffer;
}

// Where a run's simulation plays: the device the panel plays on (none: nowhere) and its actuator.
struct RigActuatorTarget {
  std::optional<playback::OutputSettings> device;
  std::string actuator;  // a calibration's name or file; empty: none
};

// The run's player, turned on and off as the view asks: called on the capture's thread between
// blocks of frames, so the player is only ever touched there. A device that does not open is said
// in the feed and tried again only when asked again.
class RigActuatorSwitch {
 public:
  // `player` null: `why_not` says why the simulation cannot play on the actuator in this run.
  RigActuatorSwitch(std::unique_ptr<rig::ActuatorPlayer> player, std::string why_not,
                    std::shared_ptr<std::atomic<bool>> wanted, std::shared_ptr<RigFeed> feed)
      : player_(std::move(player)), why_not_(std::move(why_not)), wanted_(std::move(wanted)), feed_(std::move(feed)) {}
  ~RigActuatorSwitch() {
    player_.reset();
    say(false, "");
  }

  void apply() {
    const bool wanted = wanted_->load();
    if (wanted == asked_) return follow_stream();
    asked_ = wanted;
    if (!wanted) {
      if (player_) player_->stop();
      say(false, "");
    } else if (!player_) {
      say(false, why_not_);
    } else {
      try {
        player_->play();
        lost_ = false;
        say_playing();
      } catch (const std::exception& e) {
        say(false, e.what());
      }
    }
  }

 private:
  // The player's own stream: a device lost while it plays (a JACK server gone) is said, and said
  // again when the stream is back.
  void follow_stream() {
    if (!asked_ || !player_ || !player_->playing()) return;
    const bool lost = player_->output_status() == playback::OutputStatus::lost;
    if (lost == lost_) return;
    lost_ = lost;
    if (lost)
      say(false, "the simulation is not heard: the device is lost (" + player_->last_problem() + ")");
    else
      say_playing();
  }
  void say_playing() {
    const auto info = *player_->stream_info();
    say(true, "playing " + player_->sound_name() + " on " + info.api + " '" + info.device + "' channel " +
                  std::to_string(player_->device().output_channel));
  }
  void say(bool playing, std::string state) {
    std::lock_guard lock(feed_->mutex);
    feed_->actuator_playing = playing;
    feed_->actuator_state = std::move(state);
  }
  std::unique_ptr<rig::ActuatorPlayer> player_;
  std::string why_not_;
  std::shared_ptr<std::atomic<bool>> wanted_;
  std::shared_ptr<RigFeed> feed_;
  bool asked_ = false;
  bool lost_ = false;
};

// The view's field a refused request names, as its controls are labelled.
const char* rig_form_field(rig::RigRequestRefused::Field field) {
  using Field = rig::RigRequestRefused::Field;
  switch (field) {
    case Field::rig:
      return "rig";
    case Field::tool:
      return "tool";
    case Field::surface:
      return "surface";
    case Field::load:
      return "load";
    case Field::speedup:
      return "speed-up";
    case Field::accelerometer:
      return "accelerometer";
    case Field::input_channel:
      return "input channel";
    case Field::replay:
      return "session";
    case Field::profile:
      return "profile";
    case Field::seconds:
      return "seconds";
    case Field::simulate:
      return "simulate";
  }
  return "rig";
}

rig::ComparisonRun run_on_rig(const RigChoice& c, const std::filesystem::path& catalog,
                              const std::filesystem::path& forcing,
                              const std::filesystem::path& folder,
                              const std::shared_ptr<RigFeed>& feed, const RigActuatorTarget& target,
                              const std::shared_ptr<std::atomic<bool>>& play_wanted,
                              JobControl& control) {
  rig::ComparisonRequest request;
  request.rig = rig_request_of(c);
  // A replay runs what it recorded: the profile chosen in the view is for the other rigs.
  if (request.rig.kind != rig::RigKind::replay) request.profile = c.profile;
  if (c.seconds > 0) request.seconds = c.seconds;
  request.simulate = c.simulated_tool;
  request.sounds.catalog = catalog;
  request.sounds.forcing_model = forcing;
  request.session = folder;
  std::optional<rig::ComparisonStart> started;
  try {
    started.emplace(std::move(request));
    control.message("opening the rig and making its simulation");
    started->open();
  } catch (const rig::RigRequestRefused& e) {
    throw std::invalid_argument(std::string(rig_form_field(e.field())) + ": " + e.what());
  }
  rig::ComparisonStart& start = *started;
  const model::design::ToolSound& sound = start.simulated();
  {
    std::lock_guard lock(feed->mutex);
    feed->rig_name = start.rig().description().name;
    feed->simulated_name = sound.name;
  }
  // Made whether or not it plays yet, since it must listen to the rig from its start; a calibration
  // that no longer reads keeps the simulation off the actuator, not the rig from running.
  std::unique_ptr<rig::ActuatorPlayer> player;
  std::string why_not = "no device is open: choose one in the devices view and start the rig again";
  if (target.device) {
    rig::ActuatorPlayerSettings settings;
    settings.device = *target.device;
    settings.actuator = target.actuator;
    try {
      player = std::make_unique<rig::ActuatorPlayer>(start.rig(), sound, settings);
    } catch (const std::exception& e) {
      why_not = e.what();
    }
  }
  RigActuatorSwitch actuator(std::move(player), std::move(why_not), play_wanted, feed);
  actuator.apply();
  rig::ComparisonHooks hooks;
  hooks.cancel = control.stop_token();
  hooks.on_progress = [feed, &control](const rig::CaptureProgress& p) {
    control.progress(p.duration_s > 0 ? p.seconds / p.duration_s : 0.0);
    std::lock_guard lock(feed->mutex);
    feed->progress = p;
  };
  std::size_t decimate = 0;
  hooks.on_data = [feed, decimate, &actuator](const rig::RigData& data) mutable {
    actuator.apply();
    std::lock_guard lock(feed->mutex);
    for (const auto& f : data.frames)
      if (decimate++ % 10 == 0) {  // 1 kHz frames, 100 Hz traces
        feed->speed_mm_s.push_back(f.speed_m_s * 1e3f);
        feed->force_n.push_back(f.normal_force_N);
      }
    while (feed->speed_mm_s.size() > kTraceFrames)
      feed->speed_mm_s.pop_front(), feed->force_n.pop_front();
  };
  rig::WaterfallRows rows;
  std::uint64_t seen_version = 0;
  hooks.on_update = [feed, rows, seen_version](rig::LiveComparison& live) mutable {
    live.take_new_rows(rows);
    std::optional<rig::ComparisonTable> table;
    if (live.table_version() != seen_version)
      seen_version = live.table_version(), table = live.table();
    std::lock_guard lock(feed->mutex);
    if (feed->frequencies_hz.empty()) feed->frequencies_hz = live.frequencies_hz();
    feed->measured_db.insert(feed->measured_db.end(), rows.measured_db.begin(), rows.measured_db.end());
    feed->simulated_db.insert(feed->simulated_db.end(), rows.simulated_db.begin(), rows.simulated_db.end());
    if (table) feed->table = std::move(table);
  };
  control.message("running " + start.profile().description());
  return start.run(hooks);
}

}  // namespace

RigView::RigView(std::filesystem::path catalog, std::filesystem::path forcing, std::filesystem::path sessions)
    : catalog_(std::move(catalog)), forcing_(std::move(forcing)), sessions_(std::move(sessions)) {}

RigView::~RigView() {
  job_.reset();  // the job is stopped: the capture finishes its session
}

void RigView::start() {
  if (running()) return;
  error_.clear();
  finished_.clear();
  feed_ = std::make_shared<RigFeed>();
  measured_.reset(), simulated_.reset(), difference_.reset();
  speed_mm_s_.clear(), force_n_.clear();
  table_.reset();
  const auto folder = sessions_ / ("rig-" + timestamp());
  RigActuatorTarget target;
  if (audio_ && audio_->device()) {
    target.device = output_settings_of(*audio_->device(), "nibrig-panel-rig");
    target.actuator = audio_->audition().actuator();
  }
  play_wanted_->store(false);  // said again below, once the run exists
  job_ = std::make_unique<BackgroundJob<rig::ComparisonRun>>(
      "rig", [c = choice_, catalog = catalog_, forcing = forcing_, folder, feed = feed_, target,
              wanted = play_wanted_](JobControl& control) {
        return run_on_rig(c, catalog, forcing, folder, feed, target, wanted, control);
      });
  follow_play_choice();
}

void RigView::stop() {
  if (job_) job_->cancel();
}

void RigView::follow_play_choice() {
  const bool turned_on = choice_.play_on_actuator && !play_wanted_->load();
  play_wanted_->store(choice_.play_on_actuator);
  // What the audition plays would sound on the actuator beside the simulation: it falls silent.
  if (turned_on && running() && audio_) audio_->stop();
}

void RigView::take_feed() {
  std::vector<float> measured, simulated;
  std::size_t bins = 0;
  {
    std::lock_guard lock(feed_->mutex);
    bins = feed_->frequencies_hz.size();
    if (shown_hz_.empty() && !feed_->frequencies_hz.empty())
      for (double f : feed_->frequencies_hz)
        if (f <= kShownMaxHz) shown_hz_.push_back(f);
    measured.swap(feed_->measured_db);
    simulated.swap(feed_->simulated_db);
    speed_mm_s_.assign(feed_->speed_mm_s.begin(), feed_->speed_mm_s.end());
    force_n_.assign(feed_->force_n.begin(), feed_->force_n.end());
    if (feed_->table) table_ = std::move(feed_->table), feed_->table.reset();
    progress_ = feed_->progress;
    rig_name_ = feed_->rig_name;
    simulated_name_ = feed_->simulated_name;
    actuator_playing_ = feed_->actuator_playing;
    actuator_state_ = feed_->actuator_state;
  }
  if (shown_hz_.empty() || measured.empty()) return;
  const std::size_t shown = shown_hz_.size();
  if (!measured_) {
    measured_ = std::make_unique<Waterfall>(shown, kWaterfallRows, Waterfall::Scale::sequential, kLowDb, kHighDb);
    simulated_ = std::make_unique<Waterfall>(shown, kWaterfallRows, Waterfall::Scale::sequential, kLowDb, kHighDb);
    difference_ = std::make_unique<Waterfall>(shown, kWaterfallRows, Waterfall::Scale::diverging, 0.0f, kDifferenceSpanDb);
  }
  std::vector<float> diff(shown);
  const std::size_t rows = std::min(measured.size(), simulated.size()) / bins;
  for (std::size_t r = 0; r < rows; ++r) {
    const float* m = measured.data() + r * bins;
    const float* s = simulated.data() + r * bins;
    for (std::size_t k = 0; k < shown; ++k) diff[k] = s[k] - m[k];
    measured_->push_row(m);
    simulated_->push_row(s);
    difference_->push_row(diff.data());
  }
}

void RigView::draw() {
  if (job_ && job_->done()) {
    error_ = job_->error();
    if (auto run = job_->take_result()) {
      table_ = run->table;
      finished_ = "session " + run->capture.folder.string() + (run->capture.complete ? "" : " (" + run->capture.record.ended_because + ")");
    }
    job_.reset();
  }
  follow_play_choice();
  take_feed();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ImGui::BeginChild("rig-controls", {320.0f, avail.y});
  draw_controls();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("rig-live", {0.0f, avail.y});
  draw_waterfalls();
  draw_traces();
  draw_table();
  ImGui::EndChild();
}

void RigView::draw_controls() {
  section("Rig");
  const char* kinds[] = {"simulated", "replay a session", "USB controller"};
  ImGui::Combo("rig", &choice_.kind, kinds, 3);
  if (choice_.kind == 1) input_text("session", choice_.replay);
  if (choice_.kind == 2) {
    input_text("serial", choice_.usb_serial);
    input_text("input api", choice_.input_api);
    input_text("input device", choice_.input_device);
    ImGui::InputInt("input channel", &choice_.input_channel);
  }
  input_text("tool", choice_.tool);
  input_text("surface", choice_.surface);
  input_text("simulate", choice_.simulated_tool);
  if (choice_.kind != 1) input_text("profile", choice_.profile);
  ImGui::SliderFloat("seconds", &choice_.seconds, 0.0f, 60.0f, "%.0f");
  if (choice_.kind != 2) ImGui::SliderFloat("speed-up", &choice_.speedup, 1.0f, 8.0f, "%.0f x");
  ImGui::Checkbox("play the simulation on the actuator", &choice_.play_on_actuator);
  bool heard = false;
  if (const std::string line = actuator_line(&heard); !line.empty()) {
    if (heard) ImGui::TextWrapped("%s", line.c_str());
    else ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", line.c_str());
  }
  if (!running()) {
    if (ImGui::Button("Start")) start();
  } else {
    if (ImGui::Button("Stop")) stop();
    ImGui::SameLine();
    ImGui::ProgressBar(static_cast<float>(job_->progress()), {-1.0f, 0.0f}, job_->message().c_str());
  }
  if (!rig_name_.empty()) ImGui::TextWrapped("%s", rig_name_.c_str());
  if (!simulated_name_.empty()) ImGui::TextWrapped("simulated: %s", simulated_name_.c_str());
  if (progress_.duration_s > 0)
    ImGui::Text("%.1f of %.1f s, %.0f mm/s, %llu frames dropped", progress_.seconds, progress_.duration_s,
                progress_.speed_m_s * 1e3, static_cast<unsigned long long>(progress_.dropped_frames));
  if (!finished_.empty()) ImGui::TextWrapped("%s", finished_.c_str());
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
}

void RigView::draw_waterfalls() {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float w = (avail.x - 40.0f) / 3.0f, h = std::max(120.0f, avail.y * 0.5f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const char* titles[] = {"measured (time runs down)", "simulated", "simulated - measured, +-20 dB"};
  Waterfall* falls[] = {measured_.get(), simulated_.get(), difference_.get()};
  // Each title wraps inside its own column: in a narrow window they would run into each other.
  float title_h = 0.0f;
  for (const char* t : titles) title_h = std::max(title_h, ImGui::CalcTextSize(t, nullptr, false, w).y);
  for (int i = 0; i < 3; ++i) {
    const ImVec2 min{at.x + i * (w + 20.0f), at.y + title_h + 4.0f}, max{min.x + w, min.y + h};
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), {min.x, at.y}, IM_COL32(230, 230, 230, 255), titles[i],
                  nullptr, w);
    if (falls[i]) falls[i]->draw(draw, min, max);
    else draw->AddRectFilled(min, max, IM_COL32(30, 30, 34, 255));
    draw->AddRect(min, max, IM_COL32(255, 255, 255, 90));
    char label[32];
    std::snprintf(label, sizeof label, "%.0f Hz", shown_hz_.empty() ? kShownMaxHz : shown_hz_.back());
    draw->AddText({min.x, max.y + 2.0f}, IM_COL32(200, 200, 200, 255), "0 Hz");
    draw->AddText({max.x - ImGui::CalcTextSize(label).x, max.y + 2.0f}, IM_COL32(200, 200, 200, 255), label);
    rects_[i] = {min, max};
  }
  ImGui::Dummy({avail.x, h + title_h + 26.0f});
}

void RigView::draw_traces() {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float h = 90.0f;
  std::vector<double> x(speed_mm_s_.size()), speed(speed_mm_s_.begin(), speed_mm_s_.end()),
      force(force_n_.begin(), force_n_.end());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (static_cast<double>(i) - static_cast<double>(x.size())) * 0.01;
  const PlotFrame speed_frame({at.x + 50.0f, at.y + 18.0f}, {avail.x * 0.5f - 70.0f, h}, {-10.0, 0.0}, {0.0, 260.0});
  const PlotFrame force_frame({at.x + avail.x * 0.5f + 30.0f, at.y + 18.0f}, {avail.x * 0.5f - 70.0f, h}, {-10.0, 0.0},
                              {0.0, 5.0});
  draw_axes(draw, speed_frame, "s", "speed mm/s");
  draw_axes(draw, force_frame, "s", "normal force N");
  draw_trace(draw, speed_frame, x, speed, IM_COL32(86, 180, 233, 255));
  draw_trace(draw, force_frame, x, force, IM_COL32(230, 159, 0, 255));
  ImGui::Dummy({avail.x, h + 50.0f});
}

void RigView::draw_table() {
  if (!table_) return;
  section("Distance per speed (simulated against measured)");
  if (!table_->failure.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "analysis stopped: %s", table_->failure.c_str());
  if (ImGui::BeginTable("rig-bins", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableSetupColumn("speed mm/s");
    ImGui::TableSetupColumn("rows");
    ImGui::TableSetupColumn("LSD dB");
    ImGui::TableSetupColumn("weighted mean, log10 sim/meas");
    ImGui::TableHeadersRow();
    for (const auto& b : table_->bins) {
      if (b.rows == 0) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%.0f-%.0f", b.min_speed_m_s * 1e3, b.max_speed_m_s * 1e3);
      ImGui::TableNextColumn();
      ImGui::Text("%zu", b.rows);
      ImGui::TableNextColumn();
      ImGui::Text("%.1f", b.lsd_db);
      ImGui::TableNextColumn();
      ImGui::Text("%+.2f", b.weighted_mean_log10_difference);
    }
    ImGui::EndTable();
  }
  ImGui::Text("mean LSD %.1f dB over %zu speed bins", table_->summary.mean_lsd_db, table_->summary.bins_with_rows);
}

rig::RigRequest rig_request_of(const RigChoice& c) {
  rig::RigRequest request;
  request.kind = c.kind == 0 ? rig::RigKind::simulated : c.kind == 1 ? rig::RigKind::replay : rig::RigKind::usb;
  request.tool = c.tool;
  request.surface = c.surface;
  request.speedup = c.speedup;
  request.replay = c.replay;
  request.usb_serial = c.usb_serial;
  request.input_api = c.input_api;
  request.input_device = c.input_device;
  // Not clamped: 0 or less is refused by the rig's check, naming the field.
  request.input_channel = static_cast<unsigned>(std::max(0, c.input_channel));
  return request;
}

std::string RigView::actuator_line(bool* heard) const {
  if (heard) *heard = false;
  if (actuator_state_.empty()) return {};
  if (heard) *heard = actuator_playing_;
  return actuator_state_;
}

}  // namespace nibrig::ui::panel
