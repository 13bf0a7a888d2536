#include "ui/panel/devices_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rig/usb/usb_protocol.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

DevicesView::DevicesView(PanelAudio& audio) : audio_(audio) {}

void DevicesView::set_request(const DeviceRequest& request) {
  request_ = request;
  std::snprintf(api_, sizeof api_, "%s", request.api.c_str());
  std::snprintf(device_, sizeof device_, "%s", request.device.c_str());
}

void DevicesView::refresh() {
  if (job_) return;
  job_ = std::make_unique<BackgroundJob<DeviceListing>>("listing devices", [](JobControl& control) {
    DeviceListing listing;
    control.message("audio devices");
    listing.apis = playback::list_devices();
    control.message("USB rig controllers");
    try {
      listing.controllers = rig::usb::list_rig_controllers();
    } catch (const std::exception& e) {
      listing.usb_problem = e.what();
    }
    control.message("pen tablets");
    listing.tablets = rig::pen::list_tablets(&listing.tablet_problem);
    return listing;
  });
}

DeviceRequest DevicesView::shown_request() const {
  DeviceRequest r = request_;
  r.api = api_;
  r.device = device_;
  return r;
}

void DevicesView::open() {
  request_.api = api_;
  request_.device = device_;
  error_ = audio_.open(request_);
  shown_stream_.reset();  // the form shows what this one runs, even when it is the same as before
}

void DevicesView::show_what_runs(const playback::StreamInfo& info) {
  auto stream = std::make_tuple(info.api, info.device, info.sample_rate, info.period_frames);
  if (shown_stream_ == stream) return;  // what the person types in since stays
  std::snprintf(api_, sizeof api_, "%s", info.api.c_str());
  std::snprintf(device_, sizeof device_, "%s", info.device.c_str());
  request_.api = info.api;
  request_.device = info.device;
  request_.period_frames = info.period_frames;
  shown_stream_ = std::move(stream);
}

void DevicesView::draw() {
  if (job_ && job_->done()) {
    if (auto listing = job_->take_result()) listing_ = std::move(listing);
    if (!job_->error().empty()) error_ = job_->error();
    job_.reset();
  }
  if (!listing_ && !job_) refresh();
  if (const auto info = audio_.audition().stream_info()) show_what_runs(*info);
  else shown_stream_.reset();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ImGui::BeginChild("devices-choice", {avail.x * 0.5f, avail.y});
  // Every field leaves room for the longest label beside it, so that none is cut at the smallest
  // window (800 pixels: half of it is this column).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float label = std::ceil(std::max(ImGui::CalcTextSize("api (jack, alsa, pulse)").x,
                                         ImGui::CalcTextSize(RoundTripSection::kWidestLabel).x)) +
                      style.ItemInnerSpacing.x + 1.0f;  // + 1: positions are whole pixels
  ImGui::PushItemWidth(-label);
  section("Output to the actuator");
  ImGui::InputText("api (jack, alsa, pulse)", api_, sizeof api_);
  ImGui::InputText("device (by name)", device_, sizeof device_);
  int channel = static_cast<int>(request_.output_channel), period = static_cast<int>(request_.period_frames);
  if (ImGui::InputInt("output channel", &channel)) request_.output_channel = static_cast<unsigned>(std::max(1, channel));
  if (ImGui::InputInt("period frames", &period)) request_.period_frames = static_cast<unsigned>(std::clamp(period, 16, 8192));
  if (ImGui::Button("Open")) open();
  ImGui::SameLine();
  if (ImGui::Button("Close")) audio_.close();
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
  draw_stream();
  section("Actuator calibration");
  ImGui::SetNextItemWidth(-(std::ceil(ImGui::CalcTextSize("name or file").x + ImGui::CalcTextSize("Use").x) +
                            style.ItemInnerSpacing.x + 2.0f * style.FramePadding.x + style.ItemSpacing.x + 1.0f));
  ImGui::InputText("name or file", actuator_, sizeof actuator_);
  ImGui::SameLine();
  if (ImGui::Button("Use")) {
    error_ = audio_.use_actuator(actuator_);
  }
  ImGui::TextWrapped("in use: %s", audio_.audition().actuator().empty() ? "none (the output is the requested m/s2 times a plain gain)"
                                                                : audio_.audition().actuator().c_str());
  round_trip_.draw(shown_request());
  ImGui::PopItemWidth();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("devices-listing", {0.0f, avail.y});
  draw_listing();
  ImGui::EndChild();
}

void DevicesView::sample() {
  const auto& a = audio_.audition();
  const auto info = a.stream_info();
  if (!info) {
    running_.reset();
    monitor_.reset();
    return;
  }
  const auto stats = *a.output_stats();
  const auto engine = a.engine_stats();
  monitor_.sample(std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count(), engine,
                  stats.output_underflows);
  RunningStream r;
  r.api = info->api;
  r.device = info->device;
  r.sample_rate = info->sample_rate;
  r.period_frames = info->period_frames;
  const double period_s = info->sample_rate ? static_cast<double>(info->period_frames) / info->sample_rate : 0.0;
  r.period_ms = 1e3 * period_s;
  r.latency_reported = info->latency_frames > 0;
  r.latency_frames = r.latency_reported ? info->latency_frames : static_cast<long>(info->period_frames);
  r.latency_ms = info->sample_rate ? 1e3 * static_cast<double>(r.latency_frames) / info->sample_rate : 0.0;
  r.load = monitor_.load(period_s);
  r.xruns = monitor_.xruns();
  running_ = r;
}

void DevicesView::draw_stream() {
  section("Stream");
  sample();
  if (!running_) {
    ImGui::TextWrapped("No device open: the panel plays nowhere (choose one and press Open).");
    return;
  }
  const RunningStream& r = *running_;
  const auto& a = audio_.audition();
  const auto stats = *a.output_stats();
  const auto engine = a.engine_stats();
  ImGui::Text("running: %s '%s' at %u Hz", r.api.c_str(), r.device.c_str(), r.sample_rate);
  ImGui::Text("period: %.2f ms (%u frames)", r.period_ms, r.period_frames);
  if (r.latency_reported)
    ImGui::TextWrapped("output latency: %.2f ms (%ld frames, as %s reports it)", r.latency_ms, r.latency_frames, r.api.c_str());
  else
    ImGui::TextWrapped("output latency: at least %.2f ms (one period; %s reports none)", r.latency_ms, r.api.c_str());
  if (r.load) {
    // Past the period a block is late: the device plays silence or the previous block.
    const bool late = r.load->worst >= 1.0;
    if (late) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("callback load: %.1f%% of the period on average, %.0f%% at worst (last %.0f s, %llu blocks)",
                100.0 * r.load->mean, 100.0 * r.load->worst, r.load->window_s,
                static_cast<unsigned long long>(r.load->blocks));
    if (late) ImGui::PopStyleColor();
  } else {
    ImGui::TextUnformatted("callback load: no block has run in the last seconds");
  }
  // A whole minute once the view has been shown that long (to one sample's precision).
  const bool minute = r.xruns.window_s >= StreamMonitor::kXrunWindowS - StreamMonitor::kSampleEveryS;
  const std::string when = minute ? std::string("the last minute")
                                  : "the last " + std::to_string(static_cast<long>(r.xruns.window_s)) +
                                        " s (counted since the stream opened)";
  ImGui::TextWrapped("xruns in %s: %llu from the device, %llu of our own (blocks rendered past the period)", when.c_str(),
              static_cast<unsigned long long>(r.xruns.device), static_cast<unsigned long long>(r.xruns.own));
  ImGui::Text("status: %s", *a.output_status() == playback::OutputStatus::running ? "running" : "LOST, looking for it");
  if (!a.last_problem().empty()) ImGui::TextWrapped("last problem: %s", a.last_problem().c_str());
  ImGui::Text("device losses: %llu, reconnects: %llu", static_cast<unsigned long long>(stats.losses),
              static_cast<unsigned long long>(stats.reconnects));
  ImGui::Text("peak output %.2f of full scale, %llu samples limited", engine.peak_output,
              static_cast<unsigned long long>(engine.limited_samples));
}

void DevicesView::draw_listing() {
  section("Audio back ends and devices");
  if (ImGui::Button(job_ ? "Listing..." : "Refresh")) refresh();
  if (!listing_) return;
  for (const auto& api : listing_->apis) {
    if (!api.available) {
      ImGui::TextDisabled("%s: %s", api.display_name.c_str(), api.unavailable_reason.c_str());
      continue;
    }
    ImGui::Text("%s", api.display_name.c_str());
    for (const auto& d : api.devices) {
      ImGui::BulletText("%s (%u out, %u in)%s", d.name.c_str(), d.output_channels, d.input_channels,
                        d.default_output ? ", default" : "");
      ImGui::SameLine();
      ImGui::PushID(&d);
      if (ImGui::SmallButton("choose")) {
        std::snprintf(api_, sizeof api_, "%s", api.api.c_str());
        std::snprintf(device_, sizeof device_, "%s", d.name.c_str());
      }
      ImGui::PopID();
    }
  }
  section("USB rig controllers");
  if (!listing_->usb_problem.empty()) ImGui::TextWrapped("%s", listing_->usb_problem.c_str());
  else if (listing_->controllers.empty())
    ImGui::TextWrapped("none on the bus (VID 0x%04X, PID 0x%04X)", rig::usb::kVendorId, rig::usb::kProductId);
  for (const auto& c : listing_->controllers) ImGui::BulletText("%s", rig::usb::describe(c).c_str());
  section("Pen tablets (the pad draws with the first)");
  if (listing_->tablets.empty()) {
    ImGui::TextWrapped("none%s%s", listing_->tablet_problem.empty() ? "" : ": ", listing_->tablet_problem.c_str());
  }
  for (const auto& t : listing_->tablets) {
    ImGui::BulletText("%s%s  %s  %.1f x %.1f mm, %s, %s", t.name.c_str(), t.model.empty() ? "" : (" (" + t.model + ")").c_str(),
                      t.devnode.c_str(), t.width_mm, t.height_mm, t.has_pressure ? "pressure" : "no pressure",
                      t.has_tilt ? "tilt" : "no tilt");
  }
}

}  // namespace nibrig::ui::panel
