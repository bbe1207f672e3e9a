#pragma once
// SPDX-License-Identifier: MIT
// The versions of the shape of `collide data`'s CSV and JSON (docs/data-format.md). Version 2
// (the default) books energy so that every row adds up to the start and logs every event with
// its kind; version 1 is the older shape, kept for scripts written against it
// (`--data-version 1`).
namespace collide::report {

inline constexpr int kDataVersion = 2;        // written unless asked otherwise
inline constexpr int kOldestDataVersion = 1;  // the oldest still written

}  // namespace collide::report
