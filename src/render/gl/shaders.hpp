#pragma once
// Private: GLSL sources from shaders/, compiled into the library by collide_embed_shaders.
namespace collide::render::shaders {

extern const char* const shape_vert;
extern const char* const shape_frag;
extern const char* const text_vert;
extern const char* const text_frag;
extern const char* const fill_vert;
extern const char* const fill_frag;

}  // namespace collide::render::shaders
