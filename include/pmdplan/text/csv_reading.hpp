#pragma once
// What every CSV reader of pmdplan (glove recordings, posture tables) does before it reads rows.
#include <string_view>

namespace pmdplan {

/// `text` without a leading UTF-8 byte order mark (EF BB BF): spreadsheet programs write one at
/// the start of CSV they export as UTF-8, as an encoding marker, not as part of the first column's
/// name (Python reads such files with the "utf-8-sig" codec for the same reason). A mark anywhere
/// else is kept, and a reader reports it as the character it is.
std::string_view withoutByteOrderMark(std::string_view text);

}  // namespace pmdplan
