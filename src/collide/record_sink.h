// What a certified test records into: nothing (NoRecords, which the compiler removes), or the
// harness's Records (bound_records.h), reached through RecordsRef so that a test's own file
// needs neither the other tests' records nor their headers.
#pragma once

#include <vector>

namespace cc::bounds {

/// Every certified quantity of one or more probed calls (bound_records.h).
struct Records;

/// A new Records at the end of `calls`, for one more probed call (bound_records.cpp): so that a
/// probe needs no more than this header.
Records& next_call(std::vector<Records>& calls);

/// Appends `record` to `records`; defined in bound_records.cpp for every record type.
template <class Record>
void record(Records& records, const Record& record);

/// A Records as a certified test writes into it.
struct RecordsRef {
  Records& records;
  template <class Record>
  void add(const Record& r) {
    record(records, r);
  }
};

/// What the plain tests record into: nothing.
struct NoRecords {
  template <class Record>
  void add(const Record&) {}
};

}  // namespace cc::bounds
