// SPDX-License-Identifier: MIT
#pragma once
// Private: Mesa keeps the shaders it compiles in a folder of the user's cache. Where it cannot
// make that folder it says so on stderr ("Failed to create ... for shader cache (No such file or
// directory)---disabling.") on every run, whatever -q asks: an XDG_CACHE_HOME whose parent is
// missing is enough. Then this process runs without the cache, as Mesa would, but silently.

namespace collide::render {

// Sets MESA_SHADER_CACHE_DISABLE for this process when the folder Mesa would use for its shader
// cache cannot be made, and nobody chose already; before the first GL context (Mesa reads its
// environment when it starts a screen). Once per process; later calls do nothing.
void switchOffAnUnusableShaderCache();

}  // namespace collide::render
