// SPDX-License-Identifier: MIT
#pragma once
// What wrapping reads of numbers in text (text_wrap.cpp): digits of the scripts collide writes
// numbers in, signs, a vector's brackets, list marks and a direction's angle, so a number stays
// with its unit and a speed with its direction.
#include <cstddef>
#include <string_view>

namespace collide::text {

// A decimal digit of the scripts collide writes numbers in: ASCII (U+0030..9), Arabic-Indic
// (U+0660..9), Eastern Arabic-Indic (U+06F0..9) and Devanagari (U+0966..F).
bool isScriptDigit(char32_t c);

// The code point a UTF-8 sequence starting at `at` encodes (0 where it is cut short).
char32_t utf8CodePointAt(std::string_view text, std::size_t at);

// Whether `text` starts with a digit of those scripts.
bool startsWithDigit(std::string_view text);

// Whether `text` ends with a digit of those scripts.
bool endsWithDigit(std::string_view text);

// A sign that belongs to the number after it: "+", "−", or Arabic's letter mark and minus.
bool startsWithSign(std::string_view word);

// A vector's closing bracket after its last number, "0)" or "−0,500)": its unit follows
// ("(2,00; 0) kg·m/s") and stays with it where a line holds both.
bool endsWithNumberInBrackets(std::string_view text);

// The brackets `word` leaves open (negative: it closes more than it opens).
int bracketsOpened(std::string_view word);

// A mark after which a list goes on (",", "，", "、", Arabic "،") or a clause does (";", "；").
bool endsWithListMark(std::string_view text);

// A direction, "2°" or "−143°" (a list mark may follow): after its speed's "m/s," it is one
// quantity with it.
bool isAngle(std::string_view word);

}  // namespace collide::text
