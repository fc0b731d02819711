// c2f-plot: draws anytime traces (CSV: time_s,level,step,energy,num_vars[,error]) as PNG line
// plots of energy against time and, when every trace has it, error against time.
//
// Usage: c2f-plot -o PLOT.png [--title T] [--column energy|error] [--gap-to E]
//                 NAME=TRACE.csv [NAME=TRACE.csv ...]

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "c2f/core/number_text.hpp"
#include "c2f/core/output_file.hpp"
#include "c2f/core/text_input.hpp"
#include "staged_file.hpp"
#include "tool_options.hpp"

namespace {

struct Series {
  std::string name;
  std::vector<double> time, value;
};

/// The largest magnitude a plotted value (or a --gap-to reference) may have.
constexpr double kMaxPlotValue = 1e300;

Series read_trace(const std::string& name, const std::string& path, const std::string& column) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open trace '" + path + "'");
  std::string header;
  std::getline(in, header);
  std::vector<std::string> columns;
  std::stringstream hs{std::string(c2f::without_byte_order_mark(header))};
  for (std::string c; std::getline(hs, c, ',');) columns.push_back(c);
  const auto time_col = std::find(columns.begin(), columns.end(), "time_s") - columns.begin();
  const auto value_col = std::find(columns.begin(), columns.end(), column) - columns.begin();
  if (time_col == static_cast<long>(columns.size()) ||
      value_col == static_cast<long>(columns.size())) {
    throw std::runtime_error("trace '" + path + "' has no time_s or " + column + " column");
  }
  Series series{name, {}, {}};
  std::string line;
  for (int number = 2; std::getline(in, line); ++number) {
    std::stringstream ls(line);
    std::vector<std::string> fields;
    for (std::string f; std::getline(ls, f, ',');) fields.push_back(f);
    if (fields.size() != columns.size()) {
      throw std::runtime_error("trace '" + path + "' line " + std::to_string(number) + " has " +
                               std::to_string(fields.size()) + " fields");
    }
    // Strict numbers: finite, times >= 0, values within what a plot axis can span.
    auto parse_field = [&](long col, bool is_time) {
      const std::string& text = fields[static_cast<std::size_t>(col)];
      const std::optional<double> value = c2f::parse_real(text);
      const bool in_range =
          value && (is_time ? *value >= 0.0 && *value <= 1e12 : std::abs(*value) <= kMaxPlotValue);
      if (!in_range) {
        throw std::runtime_error("trace '" + path + "' line " + std::to_string(number) + ": " +
                                 columns[static_cast<std::size_t>(col)] + " '" + text +
                                 (is_time ? "' is not a time in [0, 1e12] s"
                                          : "' is not a finite number within +-1e300"));
      }
      return *value;
    };
    series.time.push_back(parse_field(time_col, true));
    series.value.push_back(parse_field(value_col, false));
  }
  if (series.time.empty()) throw std::runtime_error("trace '" + path + "' has no rows");
  return series;
}

/// The smallest relative gap --gap-to draws: labelings at or below the reference sit on it.
constexpr double kGapFloor = 1e-7;

/// Replaces each value by log10 of its relative gap above `reference`, (v - reference) /
/// max(1, |reference|), floored at kGapFloor.
void to_log_gap(Series& series, double reference) {
  const double scale = std::max(1.0, std::abs(reference));
  for (double& v : series.value) v = std::log10(std::max(kGapFloor, (v - reference) / scale));
}

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, std::abs(v) >= 1000 ? "%.0f" : "%.4g", v);
  return text;
}

}  // namespace

/// Writes `plot` as the PNG `out`, staged beside it and moved into place only once written
/// (a failed write leaves an earlier plot as it was).
void write_plot(const cv::Mat& plot, const std::filesystem::path& out) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", plot, png)) throw std::runtime_error("cannot encode the plot as PNG");
  c2f::examples::StagedFile output(out);
  std::ofstream file(output.path(), std::ios::binary);
  if (!file) throw std::runtime_error("cannot write '" + out.string() + "'");
  file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  c2f::close_checked(file, "'" + out.string() + "'");
  output.commit();
}

int main(int argc, char** argv) {
  std::string out, title = "energy against time", column = "energy", gap_to;
  std::vector<std::pair<std::string, std::string>> inputs;
  return c2f::examples::run_tool("c2f-plot", [&] {
    c2f::examples::ToolOptions options(
        "c2f-plot: line plots of traces (a column against time) as PNG.\n\n"
        "Usage: c2f-plot -o PLOT.png [options] NAME=TRACE.csv ...\n\nOptions");
    options.path("out,o", &out, "the PNG to write")
        .text("title", &title, "plot title")
        .text("column", &column, "the trace column to plot: energy or error")
        .text("gap-to", &gap_to,
              "plot log10 of each value's relative gap above this reference, (v - ref) / "
              "max(1, |ref|), floored at 1e-7 (values at or below the reference sit on the "
              "floor): shows how close runs get to, e.g., flat's final energy");
    const auto arguments = options.parse(argc, argv, {"NAME=TRACE.csv ...", 64});
    if (!arguments) return 0;
    for (const std::string& argument : *arguments) {
      const std::size_t equals = argument.find('=');
      if (equals == std::string::npos || equals == 0 || equals + 1 == argument.size())
        throw std::invalid_argument("unexpected argument '" + argument +
                                    "' (expected NAME=TRACE.csv)");
      inputs.emplace_back(argument.substr(0, equals), argument.substr(equals + 1));
    }
    if (out.empty() || inputs.empty())
      throw std::invalid_argument("need -o PLOT.png and at least one NAME=TRACE.csv");
    if (std::filesystem::path(out).extension() != ".png")
      throw std::invalid_argument("-o '" + out + "': expected a file name ending in .png");
    std::optional<double> reference;
    if (!gap_to.empty()) {
      reference = c2f::parse_real(gap_to);
      if (!reference || std::abs(*reference) > kMaxPlotValue)
        throw std::invalid_argument("--gap-to: expected a finite number, got '" + gap_to + "'");
    }
    std::vector<Series> series;
    for (const auto& [name, path] : inputs) {
      series.push_back(read_trace(name, path, column));
      if (reference) to_log_gap(series.back(), *reference);
    }
    double t_max = 0, v_min = std::numeric_limits<double>::infinity(), v_max = -v_min;
    for (const Series& s : series) {
      t_max = std::max(t_max, s.time.back());
      for (double v : s.value) v_min = std::min(v_min, v), v_max = std::max(v_max, v);
    }
    if (!(v_max > v_min)) v_max = v_min + std::max(1.0, std::abs(v_min) * 1e-6);
    const int width = 900, height = 560, left = 110, right = 30, top = 50, bottom = 70;
    cv::Mat plot(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    auto px = [&](double t) {
      return left + static_cast<int>((width - left - right) * (t_max > 0 ? t / t_max : 0));
    };
    auto py = [&](double v) {
      return height - bottom -
             static_cast<int>((height - top - bottom) * (v - v_min) / (v_max - v_min));
    };
    const cv::Scalar black(0, 0, 0), grey(210, 210, 210);
    for (int k = 0; k <= 5; ++k) {
      const double t = t_max * k / 5, v = v_min + (v_max - v_min) * k / 5;
      cv::line(plot, {px(t), top}, {px(t), height - bottom}, grey);
      cv::line(plot, {left, py(v)}, {width - right, py(v)}, grey);
      cv::putText(plot, format(t), {px(t) - 15, height - bottom + 22}, cv::FONT_HERSHEY_SIMPLEX,
                  0.45, black);
      cv::putText(plot, format(v), {8, py(v) + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
    }
    cv::rectangle(plot, {left, top}, {width - right, height - bottom}, black);
    cv::putText(plot, title, {left, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.7, black, 2);
    cv::putText(plot, "time (s, run clock)", {width / 2 - 70, height - 20},
                cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
    const std::string axis = reference
                                 ? "log10 of the relative gap of " + column + " above " + gap_to +
                                       " (floor " + format(std::log10(kGapFloor)) + ")"
                                 : column;
    cv::putText(plot, axis, {8, top - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
    const cv::Scalar colours[] = {
        {200, 60, 30}, {30, 60, 220}, {40, 160, 40}, {160, 40, 160}, {0, 140, 200}};
    for (std::size_t s = 0; s < series.size(); ++s) {
      const cv::Scalar colour = colours[s % 5];
      std::vector<cv::Point> points;
      for (std::size_t i = 0; i < series[s].time.size(); ++i)
        points.emplace_back(px(series[s].time[i]), py(series[s].value[i]));
      cv::polylines(plot, points, false, colour, 2, cv::LINE_AA);
      cv::line(plot, {width - right - 200, top + 20 + 22 * static_cast<int>(s)},
               {width - right - 170, top + 20 + 22 * static_cast<int>(s)}, colour, 3);
      cv::putText(plot, series[s].name, {width - right - 160, top + 25 + 22 * static_cast<int>(s)},
                  cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
    }
    write_plot(plot, out);
    return 0;
  });
}
