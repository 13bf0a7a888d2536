#include "ui/panel/panel.hpp"

#include <atomic>
#include <cstdio>
#include <stop_token>

#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/user_cache.hpp"
#include "ui/panel/devices_view.hpp"
#include "ui/panel/pad_view.hpp"
#include "ui/panel/rig_view.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace {

constexpr View kViews[] = {View::space, View::design, View::rig, View::pad, View::devices};

std::filesystem::path sessions_folder() {
  const char* data = std::getenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  const std::filesystem::path base = data && *data ? std::filesystem::path(data)
                                                   : std::filesystem::path(home && *home ? home : ".") / ".local" / "share";
  return base / "nibrig" / "sessions";
}

}  // namespace

std::optional<View> view_named(std::string_view name) {
  for (View v : kViews)
    if (name == view_name(v)) return v;
  return std::nullopt;
}

const char* view_name(View view) {
  switch (view) {
    case View::space: return "space";
    case View::design: return "design";
    case View::rig: return "rig";
    case View::pad: return "pad";
    case View::devices: return "devices";
  }
  return "space";
}

Panel::Panel(PanelSetup setup) : setup_(std::move(setup)) {
  model::design::ToolSoundOptions sounds;
  sounds.catalog = setup_.catalog;
  sounds.forcing_model = setup_.forcing;
  audio_ = std::make_unique<PanelAudio>(sounds);
  space_view_ = std::make_unique<SpaceView>(SpaceScene{}, [this](const std::vector<ToolChoice>& tools,
                                                                  const rt::StrokeRequest& stroke) {
    audio_->play(tools, stroke);
  });
  rig_view_ = std::make_unique<RigView>(setup_.catalog, setup_.forcing, sessions_folder());
  pad_view_ = std::make_unique<PadView>(*audio_);
  design_view_ = std::make_unique<DesignView>(*audio_, setup_.catalog, setup_.forcing, setup_.design);
  devices_view_ = std::make_unique<DevicesView>(*audio_);
  if (setup_.device) {
    devices_view_->set_request(*setup_.device);
    if (const std::string e = audio_->open(*setup_.device); !e.empty()) error_ = e;
  }
  if (!setup_.space.empty()) load_space(setup_.space);
  else load_default_space();
  if (setup_.start_rig) {
    rig_view_->choice().speedup = 8.0f;
    rig_view_->start();
  }
}

Panel::~Panel() {
  // The views that play stop using the audio before it goes.
  design_view_.reset();
  pad_view_.reset();
}

void Panel::load_space(const std::filesystem::path& file) {
  space_file_ = file;
  space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
      "loading the space", [file, catalog = setup_.catalog](JobControl& control) {
        control.message("reading " + file.string());
        return load_space_file(file, catalog);
      });
}

void Panel::load_default_space() {
  space_file_.clear();
  space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
      "the default space", [catalog = setup_.catalog](JobControl& control) {
        // The cancel flag the model checks follows the job's stop request.
        std::atomic<bool> cancel{false};
        std::stop_callback on_stop(control.stop_token(), [&cancel] { cancel = true; });
        model::design::DefaultsOptions options;
        options.catalog = catalog;
        options.cancel = &cancel;
        options.progress = [&control](const std::string& step, std::size_t done, std::size_t total) {
          control.message("the default space (computed once, then kept): " + step);
          control.progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
        };
        return panel::load_default_space(options);
      });
}

void Panel::show(View view) { requested_ = view; }

bool Panel::settled() const {
  switch (current_) {
    case View::space: return !space_job_ && !audio_->making_sounds();
    case View::rig: return !rig_view_->running() || rig_view_->progress() >= 0.5;
    case View::devices: return devices_view_->listing().has_value();
    case View::design: return !space_job_ && design_view_->ready() && !design_view_->measuring_error();
    default: return true;
  }
}

void Panel::poll_jobs() {
  audio_->poll();
  if (space_job_ && space_job_->done()) {
    if (auto loaded = space_job_->take_result()) {
      for (const auto& w : loaded->warnings) error_ = w;
      design_view_->set_space(loaded->scene, loaded->map);
      space_view_->set_scene(std::move(loaded->scene));
    } else {
      error_ = space_job_->error();
    }
    space_job_.reset();
  }
}

void Panel::draw_menu() {
  if (!ImGui::BeginMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    ImGui::InputText("path", open_path_, sizeof open_path_);
    if (ImGui::MenuItem("Open space")) load_space(open_path_);
    if (ImGui::MenuItem("The default space")) load_default_space();
    ImGui::EndMenu();
  }
  ImGui::EndMenuBar();
}

std::string Panel::status_line() const {
  const auto& audition = audio_->audition();
  std::string device = "no device";
  if (const auto info = audition.stream_info()) {
    device = info->api + " " + info->device;
    if (audition.output_status() == playback::OutputStatus::lost)
      device += ": LOST (" + audition.last_problem() + "), looking for it";
  }
  std::string playing;
  for (std::size_t i = 0; i < audio_->playing().size(); ++i)
    playing += (i ? ", " : "") + std::string(1, static_cast<char>('A' + i)) + ": " + audio_->names()[i];
  return device + " | " + (playing.empty() ? "nothing playing" : playing) + " | " + audio_->stroke_description();
}

void Panel::draw_status() {
  ImGui::Separator();
  if (space_job_) {
    if (progress_with_cancel("space-job", static_cast<float>(space_job_->progress()), space_job_->message().c_str()))
      space_job_.reset();
  }
  if (audio_->making_sounds())
    ImGui::ProgressBar(static_cast<float>(audio_->making_progress()), {-1.0f, 0.0f}, audio_->making_message().c_str());
  const std::string& problem = !error_.empty() ? error_ : audio_->error();
  if (!problem.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", problem.c_str());
  ImGui::TextUnformatted(status_line().c_str());
  if (audio_->playing().size() > 1) {
    for (std::size_t i = 0; i < audio_->playing().size(); ++i) {
      ImGui::SameLine();
      const char label[2] = {static_cast<char>('A' + i), 0};
      if (ImGui::SmallButton(label)) audio_->select(i);
    }
  }
}

void Panel::draw() {
  poll_jobs();
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->WorkPos);
  ImGui::SetNextWindowSize(viewport->WorkSize);
  ImGui::Begin("nibrig-panel", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_MenuBar |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  draw_menu();
  const float status_height = ImGui::GetFrameHeightWithSpacing() * 3.0f;
  if (ImGui::BeginTabBar("views")) {
    for (View v : kViews) {
      const bool select = requested_ && *requested_ == v;
      if (ImGui::BeginTabItem(view_name(v), nullptr, select ? ImGuiTabItemFlags_SetSelected : 0)) {
        current_ = v;
        ImGui::BeginChild("view", {0.0f, -status_height});
        switch (v) {
          case View::space: space_view_->draw(); break;
          case View::design: design_view_->draw(); break;
          case View::rig: rig_view_->draw(); break;
          case View::pad: pad_view_->draw(); break;
          case View::devices: devices_view_->draw(); break;
        }
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
    }
    ImGui::EndTabBar();
  }
  if (requested_ && current_ == *requested_) requested_.reset();
  draw_status();
  ImGui::End();
}

}  // namespace nibrig::ui::panel
