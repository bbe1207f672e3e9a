#pragma once
// The document language of a PDF (the catalogue's /Lang, PDF 1.7 section 14.9.2), so screen
// readers and search read its text in the frame's language. Cairo 1.16 writes no /Lang and has no
// call to set one; it is added by a standard incremental update (section 7.5.6) appended after
// Cairo's bytes: a new revision of the catalogue object with /Lang, a cross-reference section for
// it and a trailer whose /Prev points at Cairo's.
#include <string>

namespace collide::render {

// `pdf` (one complete file, as Cairo wrote it) with /Lang (bcp47_tag) in its catalogue; unchanged
// when the tag is empty. Throws RenderError when the file's trailer or catalogue cannot be found.
std::string declarePdfLanguage(std::string pdf, const std::string& bcp47_tag);

}  // namespace collide::render
