#pragma once
// The framing of universal-file datasets 58 and 58b (uff_reader.h describes the records), shared by the
// readers of FRFs (uff_reader.h) and of dynamometer time series (cutting_data/force_record_uff.h): the
// "    -1" delimiters, other datasets skipped and counted, the 58b identifier, records 1-11 as text with
// record 6 parsed, record 7, and the values of record 12 as text or as a binary block. What the function
// type, the units and the values mean is the reader's. Every error is an FrfFileError.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "frf/frf_file_error.h"
#include "frf/text_lines.h"

namespace mx {

// Record 7: ordinate data type, number of points, abscissa spacing (even: minimum and increment).
struct Uff58Record7 {
  int ordinate_type = 0;  // 2 real single, 4 real double, 5 complex single, 6 complex double
  int points = 0;
  bool even = true;
  double x_min = 0.0;
  double x_increment = 0.0;
  int line = 0;

  bool complex() const { return ordinate_type == 5 || ordinate_type == 6; }
  bool doublePrecision() const { return ordinate_type == 4 || ordinate_type == 6; }
  // Values per point in record 12: the ordinate's parts, and the abscissa when uneven.
  std::size_t componentsPerPoint() const { return (complex() ? 2u : 1u) + (even ? 0u : 1u); }
  std::size_t values() const { return static_cast<std::size_t>(points) * componentsPerPoint(); }
};

// A dataset 58/58b up to its data.
struct Uff58Header {
  int index = 0;    // 1-based position among the file's datasets, other datasets included
  int id_line = 0;  // the line of the "58" or "58b" identifier
  bool binary = false;
  bool big_endian = false;
  std::size_t block_bytes = 0;       // 58b: the size of the binary data
  std::array<TextLine, 12> records;  // records 1-11 as text; [0] unused
  std::string name;                  // record 1, trimmed
  int function_type = 0;             // record 6 from here
  int response_node = 0, response_dir = 0, reference_node = 0, reference_dir = 0;
};

class Uff58Scanner {
 public:
  // `abscissa` names the abscissa values in messages ("frequencies", "times"); `source_name` the bytes.
  Uff58Scanner(std::string_view bytes, const std::string& source_name, std::string abscissa);

  // Moves to the next dataset 58/58b and reads its records 1-11; false at the end of the bytes. After a
  // true, the caller passes the data with data() or skip() before calling next() again.
  bool next(Uff58Header& header);
  Uff58Record7 record7(const Uff58Header& header) const;
  // Record 12's values in the file's order, then the closing delimiter; an uneven abscissa must increase.
  std::vector<double> data(const Uff58Header& header, const Uff58Record7& r7);
  void skip(const Uff58Header& header);

  int skippedDatasets() const { return skipped_datasets_; }
  // The first field of records 8-11, an integer.
  int specificDataType(const Uff58Header& header, int record) const;
  FrfFileError error(int line, const std::string& expected) const { return FrfFileError(source_, line, expected); }

 private:
  void skipToDelimiter();
  TextLine headerRecord(int record, int id_line);
  int integer(std::string_view token, const TextLine& l, const std::string& what) const;
  void readRecord6(Uff58Header& h) const;
  void readBinaryIdentifier(const TextLine& id, const std::vector<std::string_view>& t, Uff58Header& h) const;
  void closeDataset(int id_line);
  void requireBlock(const Uff58Header& h) const;
  std::string countText(const Uff58Record7& r7) const;
  std::vector<double> readAscii(const Uff58Record7& r7);
  std::vector<double> readBinary(const Uff58Header& h, const Uff58Record7& r7);

  std::string_view bytes_;
  TextLines lines_;
  std::string source_;
  std::string abscissa_;
  int index_ = 0;
  int skipped_datasets_ = 0;
};

// The units label of records 8-11 (format I10,3I5,2(1X,20A1)): columns 48-67, or the sixth blank-separated
// field of a shorter line.
std::string_view uffUnitsLabel(std::string_view record);

// +-1 x, +-2 y, +-3 z; not the rotations 4-6 or 0 (scalar).
inline bool isTranslationalUffDirection(int dir) {
  return dir != 0 && dir >= -3 && dir <= 3;
}

}  // namespace mx
