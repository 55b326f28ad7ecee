/// \file recorder.hpp
/// \brief Streaming, decimating trajectory recorder: keeps every K-th state and writes it as
/// CSV as it goes. Memory is O(1) in the number of steps: nothing is stored but the last
/// offered row (so that the final state can always be written).
#pragma once

#include <charconv>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vibook {

/// Writes a header line of column names, then rows of numbers with 17 significant digits
/// (round-trip exact for binary64). Row `step` is written when step % every == 0; finish()
/// writes the last offered row if it was not written already, so the first and the last
/// states are always in the file.
class TrajectoryRecorder {
 public:
  TrajectoryRecorder(std::ostream& out, std::vector<std::string> columns, std::int64_t every = 1)
      : out_(out), columns_(std::move(columns)), every_(every) {
    if (every_ < 1) throw std::invalid_argument("TrajectoryRecorder: every must be >= 1");
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      out_ << (i ? "," : "") << columns_[i];
    }
    out_ << '\n';
    last_.reserve(columns_.size());
  }

  std::size_t columns() const { return columns_.size(); }
  /// True when offer(step, ...) would write the row: build the row only then (and for the
  /// final step).
  bool due(std::int64_t step) const { return step % every_ == 0; }
  std::int64_t rows_written() const { return written_; }

  /// Offer the state of step `step` (monotonically increasing). `values` has one entry per
  /// column; it is copied only into a fixed-size buffer.
  template <class Row>
  void offer(std::int64_t step, const Row& values) {
    if (static_cast<std::size_t>(values.size()) != columns_.size()) {
      throw std::invalid_argument("TrajectoryRecorder: row has the wrong number of columns");
    }
    last_.assign(values.begin(), values.end());
    last_step_ = step;
    if (step % every_ == 0) write_last();
  }

  /// Write the last offered row unless it was already written. Call once at the end.
  void finish() {
    if (last_step_ >= 0 && last_written_ != last_step_) write_last();
    out_.flush();
  }

 private:
  void write_last() {
    // %.17g of each value (std::to_chars is correctly rounded, as printf is), no allocation
    // after the first row.
    line_.clear();
    for (std::size_t i = 0; i < last_.size(); ++i) {
      if (i) line_.push_back(',');
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof buf, last_[i], std::chars_format::general, 17);
      line_.append(buf, r.ptr);
    }
    line_.push_back('\n');
    out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
    last_written_ = last_step_;
    ++written_;
  }

  std::string line_;
  std::ostream& out_;
  std::vector<std::string> columns_;
  std::int64_t every_;
  std::vector<double> last_;
  std::int64_t last_step_ = -1;
  std::int64_t last_written_ = -1;
  std::int64_t written_ = 0;
};

}  // namespace vibook
