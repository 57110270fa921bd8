//! Tokens of the OpenGL ES 1.x extensions this library exposes (Khronos registry values).
//!
//! Each group starts with a `// Extension: GL_...` line; `build.rs` turns every group into one
//! `#ifndef GL_<ext>` block of `include/GLES/glext.h` (with its feature macro, tokens, function
//! pointer typedefs and prototypes). An extension without tokens still gets its marker line.
//! Keep one definition per name: a token that two extensions share lives under the first.
#![forbid(unsafe_code)]

use super::types::*;

// Extension: GL_OES_blend_equation_separate
// Separate RGB and alpha blend equations.
pub const GL_BLEND_EQUATION_RGB_OES: GLenum = 0x8009;
pub const GL_BLEND_EQUATION_ALPHA_OES: GLenum = 0x883D;

// Extension: GL_OES_blend_func_separate
// Separate RGB and alpha blend factors.
pub const GL_BLEND_DST_RGB_OES: GLenum = 0x80C8;
pub const GL_BLEND_SRC_RGB_OES: GLenum = 0x80C9;
pub const GL_BLEND_DST_ALPHA_OES: GLenum = 0x80CA;
pub const GL_BLEND_SRC_ALPHA_OES: GLenum = 0x80CB;

// Extension: GL_OES_blend_subtract
// Blend equations other than addition. GL_BLEND_EQUATION_OES shares its value with GL_BLEND_EQUATION_RGB_OES.
pub const GL_BLEND_EQUATION_OES: GLenum = 0x8009;
pub const GL_FUNC_ADD_OES: GLenum = 0x8006;
pub const GL_FUNC_SUBTRACT_OES: GLenum = 0x800A;
pub const GL_FUNC_REVERSE_SUBTRACT_OES: GLenum = 0x800B;

// Extension: GL_OES_compressed_ETC1_RGB8_texture
// ETC1 compressed RGB textures.
pub const GL_ETC1_RGB8_OES: GLenum = 0x8D64;

// Extension: GL_OES_draw_texture
// Screen-aligned textured rectangles (glDrawTex*OES).
pub const GL_TEXTURE_CROP_RECT_OES: GLenum = 0x8B9D;

// Extension: GL_OES_element_index_uint
// 32-bit element indices. The token has no suffix in the registry.
pub const GL_UNSIGNED_INT: GLenum = 0x1405;

// Extension: GL_OES_fixed_point
// The fixed-point entry points under OES-suffixed names.
pub const GL_FIXED_OES: GLenum = 0x140C;

// Extension: GL_OES_framebuffer_object
// Framebuffer and renderbuffer objects.
pub const GL_NONE_OES: GLenum = 0;
pub const GL_FRAMEBUFFER_OES: GLenum = 0x8D40;
pub const GL_RENDERBUFFER_OES: GLenum = 0x8D41;
pub const GL_RGBA4_OES: GLenum = 0x8056;
pub const GL_RGB5_A1_OES: GLenum = 0x8057;
pub const GL_RGB565_OES: GLenum = 0x8D62;
pub const GL_DEPTH_COMPONENT16_OES: GLenum = 0x81A5;
pub const GL_RENDERBUFFER_WIDTH_OES: GLenum = 0x8D42;
pub const GL_RENDERBUFFER_HEIGHT_OES: GLenum = 0x8D43;
pub const GL_RENDERBUFFER_INTERNAL_FORMAT_OES: GLenum = 0x8D44;
pub const GL_RENDERBUFFER_RED_SIZE_OES: GLenum = 0x8D50;
pub const GL_RENDERBUFFER_GREEN_SIZE_OES: GLenum = 0x8D51;
pub const GL_RENDERBUFFER_BLUE_SIZE_OES: GLenum = 0x8D52;
pub const GL_RENDERBUFFER_ALPHA_SIZE_OES: GLenum = 0x8D53;
pub const GL_RENDERBUFFER_DEPTH_SIZE_OES: GLenum = 0x8D54;
pub const GL_RENDERBUFFER_STENCIL_SIZE_OES: GLenum = 0x8D55;
pub const GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES: GLenum = 0x8CD0;
pub const GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES: GLenum = 0x8CD1;
pub const GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES: GLenum = 0x8CD2;
pub const GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_OES: GLenum = 0x8CD3;
pub const GL_COLOR_ATTACHMENT0_OES: GLenum = 0x8CE0;
pub const GL_DEPTH_ATTACHMENT_OES: GLenum = 0x8D00;
pub const GL_STENCIL_ATTACHMENT_OES: GLenum = 0x8D20;
pub const GL_FRAMEBUFFER_COMPLETE_OES: GLenum = 0x8CD5;
pub const GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES: GLenum = 0x8CD6;
pub const GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES: GLenum = 0x8CD7;
pub const GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES: GLenum = 0x8CD9;
pub const GL_FRAMEBUFFER_INCOMPLETE_FORMATS_OES: GLenum = 0x8CDA;
pub const GL_FRAMEBUFFER_UNSUPPORTED_OES: GLenum = 0x8CDD;
pub const GL_FRAMEBUFFER_BINDING_OES: GLenum = 0x8CA6;
pub const GL_RENDERBUFFER_BINDING_OES: GLenum = 0x8CA7;
pub const GL_MAX_RENDERBUFFER_SIZE_OES: GLenum = 0x84E8;
pub const GL_INVALID_FRAMEBUFFER_OPERATION_OES: GLenum = 0x0506;

// Extension: GL_OES_mapbuffer
// Mapping buffer objects into client memory.
pub const GL_WRITE_ONLY_OES: GLenum = 0x88B9;
pub const GL_BUFFER_ACCESS_OES: GLenum = 0x88BB;
pub const GL_BUFFER_MAPPED_OES: GLenum = 0x88BC;
pub const GL_BUFFER_MAP_POINTER_OES: GLenum = 0x88BD;

// Extension: GL_OES_matrix_get
// Reading matrices back as the integer bit patterns of their floats.
pub const GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES: GLenum = 0x898D;
pub const GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES: GLenum = 0x898E;
pub const GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES: GLenum = 0x898F;

// Extension: GL_OES_matrix_palette
// Vertex skinning with a palette of modelview matrices.
pub const GL_MAX_VERTEX_UNITS_OES: GLenum = 0x86A4;
pub const GL_MAX_PALETTE_MATRICES_OES: GLenum = 0x8842;
pub const GL_MATRIX_PALETTE_OES: GLenum = 0x8840;
pub const GL_MATRIX_INDEX_ARRAY_OES: GLenum = 0x8844;
pub const GL_WEIGHT_ARRAY_OES: GLenum = 0x86AD;
pub const GL_CURRENT_PALETTE_MATRIX_OES: GLenum = 0x8843;
pub const GL_MATRIX_INDEX_ARRAY_SIZE_OES: GLenum = 0x8846;
pub const GL_MATRIX_INDEX_ARRAY_TYPE_OES: GLenum = 0x8847;
pub const GL_MATRIX_INDEX_ARRAY_STRIDE_OES: GLenum = 0x8848;
pub const GL_MATRIX_INDEX_ARRAY_POINTER_OES: GLenum = 0x8849;
pub const GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES: GLenum = 0x8B9E;
pub const GL_WEIGHT_ARRAY_SIZE_OES: GLenum = 0x86AB;
pub const GL_WEIGHT_ARRAY_TYPE_OES: GLenum = 0x86A9;
pub const GL_WEIGHT_ARRAY_STRIDE_OES: GLenum = 0x86AA;
pub const GL_WEIGHT_ARRAY_POINTER_OES: GLenum = 0x86AC;
pub const GL_WEIGHT_ARRAY_BUFFER_BINDING_OES: GLenum = 0x889E;

// Extension: GL_OES_query_matrix
// Reading the current matrix in fixed point with exponents (glQueryMatrixxOES). No tokens.

// Extension: GL_OES_stencil_wrap
// Wrapping stencil increment and decrement.
pub const GL_INCR_WRAP_OES: GLenum = 0x8507;
pub const GL_DECR_WRAP_OES: GLenum = 0x8508;

// Extension: GL_OES_texture_cube_map
// Cube map textures and reflection/normal texture coordinate generation.
pub const GL_NORMAL_MAP_OES: GLenum = 0x8511;
pub const GL_REFLECTION_MAP_OES: GLenum = 0x8512;
pub const GL_TEXTURE_CUBE_MAP_OES: GLenum = 0x8513;
pub const GL_TEXTURE_BINDING_CUBE_MAP_OES: GLenum = 0x8514;
pub const GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES: GLenum = 0x8515;
pub const GL_TEXTURE_CUBE_MAP_NEGATIVE_X_OES: GLenum = 0x8516;
pub const GL_TEXTURE_CUBE_MAP_POSITIVE_Y_OES: GLenum = 0x8517;
pub const GL_TEXTURE_CUBE_MAP_NEGATIVE_Y_OES: GLenum = 0x8518;
pub const GL_TEXTURE_CUBE_MAP_POSITIVE_Z_OES: GLenum = 0x8519;
pub const GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES: GLenum = 0x851A;
pub const GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES: GLenum = 0x851C;
pub const GL_TEXTURE_GEN_MODE_OES: GLenum = 0x2500;
pub const GL_TEXTURE_GEN_STR_OES: GLenum = 0x8D60;

// Extension: GL_OES_texture_mirrored_repeat
// The mirrored-repeat texture wrap mode.
pub const GL_MIRRORED_REPEAT_OES: GLenum = 0x8370;

// Extension: GL_OES_depth24
// 24-bit depth renderbuffers.
pub const GL_DEPTH_COMPONENT24_OES: GLenum = 0x81A6;

// Extension: GL_OES_rgb8_rgba8
// 8-bit-per-channel renderbuffer formats.
pub const GL_RGB8_OES: GLenum = 0x8051;
pub const GL_RGBA8_OES: GLenum = 0x8058;

// Extension: GL_OES_stencil8
// 8-bit stencil renderbuffers.
pub const GL_STENCIL_INDEX8_OES: GLenum = 0x8D48;

// Extension: GL_EXT_texture_lod_bias
// A bias added to the computed level of detail.
pub const GL_MAX_TEXTURE_LOD_BIAS_EXT: GLenum = 0x84FD;
pub const GL_TEXTURE_FILTER_CONTROL_EXT: GLenum = 0x8500;
pub const GL_TEXTURE_LOD_BIAS_EXT: GLenum = 0x8501;

// Extension: GL_EXT_texture_format_BGRA8888
// BGRA-ordered 8-bit texture and pixel data.
pub const GL_BGRA_EXT: GLenum = 0x80E1;

// Extension: GL_EXT_texture_filter_anisotropic
// Anisotropic texture filtering.
pub const GL_TEXTURE_MAX_ANISOTROPY_EXT: GLenum = 0x84FE;
pub const GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT: GLenum = 0x84FF;

// Extension: GL_EXT_discard_framebuffer
// Telling the GL which buffers' contents need not be kept.
pub const GL_COLOR_EXT: GLenum = 0x1800;
pub const GL_DEPTH_EXT: GLenum = 0x1801;
pub const GL_STENCIL_EXT: GLenum = 0x1802;

// Extension: GL_OES_fbo_render_mipmap
// Framebuffer objects render into any mipmap level of a texture.

// Extension: GL_EXT_read_format_bgra
// glReadPixels into BGRA bytes and reversed 16-bit BGRA words (format GL_BGRA_EXT).
pub const GL_UNSIGNED_SHORT_4_4_4_4_REV_EXT: GLenum = 0x8365;
pub const GL_UNSIGNED_SHORT_1_5_5_5_REV_EXT: GLenum = 0x8366;

// Extension: GL_OES_vertex_array_object
// Named sets of vertex array state, switched by one bind.
pub const GL_VERTEX_ARRAY_BINDING_OES: GLenum = 0x85B5;

// Extension: GL_APPLE_texture_max_level
// The deepest mipmap level a texture samples.
pub const GL_TEXTURE_MAX_LEVEL_APPLE: GLenum = 0x813D;

// Extension: GL_EXT_blend_minmax
// Blend equations taking the smaller or larger of source and destination.
pub const GL_MIN_EXT: GLenum = 0x8007;
pub const GL_MAX_EXT: GLenum = 0x8008;

// Extension: GL_OES_texture_npot
// Textures of any width and height, with mipmaps and every wrap mode.

// Extension: GL_APPLE_texture_2D_limited_npot
// Non-power-of-two 2D textures (contained in GL_OES_texture_npot, which is also listed).

// Extension: GL_IMG_texture_compression_pvrtc
// PVRTC1 compressed textures at 4 and 2 bits per pixel, decoded on upload.
pub const GL_COMPRESSED_RGB_PVRTC_4BPPV1_IMG: GLenum = 0x8C00;
pub const GL_COMPRESSED_RGB_PVRTC_2BPPV1_IMG: GLenum = 0x8C01;
pub const GL_COMPRESSED_RGBA_PVRTC_4BPPV1_IMG: GLenum = 0x8C02;
pub const GL_COMPRESSED_RGBA_PVRTC_2BPPV1_IMG: GLenum = 0x8C03;

// Extension: GL_EXT_texture_compression_dxt1
// S3TC DXT1 compressed textures, decoded on upload.
pub const GL_COMPRESSED_RGB_S3TC_DXT1_EXT: GLenum = 0x83F0;
pub const GL_COMPRESSED_RGBA_S3TC_DXT1_EXT: GLenum = 0x83F1;

// Extension: GL_ANGLE_texture_compression_dxt3
// S3TC DXT3 compressed textures (explicit alpha), decoded on upload.
pub const GL_COMPRESSED_RGBA_S3TC_DXT3_ANGLE: GLenum = 0x83F2;

// Extension: GL_ANGLE_texture_compression_dxt5
// S3TC DXT5 compressed textures (interpolated alpha), decoded on upload.
pub const GL_COMPRESSED_RGBA_S3TC_DXT5_ANGLE: GLenum = 0x83F3;

// Extension: GL_EXT_compressed_ETC1_RGB8_sub_texture
// glCompressedTexSubImage2D for ETC1 images, on 4 × 4 block boundaries.

// Extension: GL_EXT_map_buffer_range
// Mapping a range of a buffer object with access flags (glMapBufferRangeEXT).
pub const GL_MAP_READ_BIT_EXT: GLbitfield = 0x0001;
pub const GL_MAP_WRITE_BIT_EXT: GLbitfield = 0x0002;
pub const GL_MAP_INVALIDATE_RANGE_BIT_EXT: GLbitfield = 0x0004;
pub const GL_MAP_INVALIDATE_BUFFER_BIT_EXT: GLbitfield = 0x0008;
pub const GL_MAP_FLUSH_EXPLICIT_BIT_EXT: GLbitfield = 0x0010;
pub const GL_MAP_UNSYNCHRONIZED_BIT_EXT: GLbitfield = 0x0020;

// Extension: GL_EXT_polygon_offset_clamp
// A bound on the polygon offset's magnitude (glPolygonOffsetClampEXT).
pub const GL_POLYGON_OFFSET_CLAMP_EXT: GLenum = 0x8E1B;

// Extension: GL_OES_required_internalformat
// Sized internal formats for glTexImage2D and glCopyTexImage2D, stored at their precision (the RGB8, RGBA8, RGB565, RGBA4 and RGB5_A1 tokens are listed with the extensions that introduced them).
pub const GL_ALPHA8_OES: GLenum = 0x803C;
pub const GL_LUMINANCE8_OES: GLenum = 0x8040;
pub const GL_LUMINANCE4_ALPHA4_OES: GLenum = 0x8043;
pub const GL_LUMINANCE8_ALPHA8_OES: GLenum = 0x8045;

// Extension: GL_OES_packed_depth_stencil
// A renderbuffer of 24-bit depth and 8-bit stencil, attachable to both points (depth-stencil textures need OES_depth_texture, which is not offered).
pub const GL_DEPTH_STENCIL_OES: GLenum = 0x84F9;
pub const GL_UNSIGNED_INT_24_8_OES: GLenum = 0x84FA;
pub const GL_DEPTH24_STENCIL8_OES: GLenum = 0x88F0;

// Extension: GL_OES_surfaceless_context
// A context current without surfaces (EGL_KHR_surfaceless_context): its default framebuffer does not exist.
pub const GL_FRAMEBUFFER_UNDEFINED_OES: GLenum = 0x8219;

// Extension: GL_KHR_debug
// Debug messages in words, message control, debug groups and object labels (ES names).
pub const GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR: GLenum = 0x8242;
pub const GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR: GLenum = 0x8243;
pub const GL_DEBUG_CALLBACK_FUNCTION_KHR: GLenum = 0x8244;
pub const GL_DEBUG_CALLBACK_USER_PARAM_KHR: GLenum = 0x8245;
pub const GL_DEBUG_SOURCE_API_KHR: GLenum = 0x8246;
pub const GL_DEBUG_SOURCE_WINDOW_SYSTEM_KHR: GLenum = 0x8247;
pub const GL_DEBUG_SOURCE_SHADER_COMPILER_KHR: GLenum = 0x8248;
pub const GL_DEBUG_SOURCE_THIRD_PARTY_KHR: GLenum = 0x8249;
pub const GL_DEBUG_SOURCE_APPLICATION_KHR: GLenum = 0x824A;
pub const GL_DEBUG_SOURCE_OTHER_KHR: GLenum = 0x824B;
pub const GL_DEBUG_TYPE_ERROR_KHR: GLenum = 0x824C;
pub const GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR_KHR: GLenum = 0x824D;
pub const GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR_KHR: GLenum = 0x824E;
pub const GL_DEBUG_TYPE_PORTABILITY_KHR: GLenum = 0x824F;
pub const GL_DEBUG_TYPE_PERFORMANCE_KHR: GLenum = 0x8250;
pub const GL_DEBUG_TYPE_OTHER_KHR: GLenum = 0x8251;
pub const GL_DEBUG_TYPE_MARKER_KHR: GLenum = 0x8268;
pub const GL_DEBUG_TYPE_PUSH_GROUP_KHR: GLenum = 0x8269;
pub const GL_DEBUG_TYPE_POP_GROUP_KHR: GLenum = 0x826A;
pub const GL_DEBUG_SEVERITY_NOTIFICATION_KHR: GLenum = 0x826B;
pub const GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR: GLenum = 0x826C;
pub const GL_DEBUG_GROUP_STACK_DEPTH_KHR: GLenum = 0x826D;
pub const GL_BUFFER_KHR: GLenum = 0x82E0;
pub const GL_SHADER_KHR: GLenum = 0x82E1;
pub const GL_PROGRAM_KHR: GLenum = 0x82E2;
pub const GL_VERTEX_ARRAY_KHR: GLenum = 0x8074;
pub const GL_QUERY_KHR: GLenum = 0x82E3;
pub const GL_PROGRAM_PIPELINE_KHR: GLenum = 0x82E4;
pub const GL_SAMPLER_KHR: GLenum = 0x82E6;
pub const GL_MAX_LABEL_LENGTH_KHR: GLenum = 0x82E8;
pub const GL_MAX_DEBUG_MESSAGE_LENGTH_KHR: GLenum = 0x9143;
pub const GL_MAX_DEBUG_LOGGED_MESSAGES_KHR: GLenum = 0x9144;
pub const GL_DEBUG_LOGGED_MESSAGES_KHR: GLenum = 0x9145;
pub const GL_DEBUG_SEVERITY_HIGH_KHR: GLenum = 0x9146;
pub const GL_DEBUG_SEVERITY_MEDIUM_KHR: GLenum = 0x9147;
pub const GL_DEBUG_SEVERITY_LOW_KHR: GLenum = 0x9148;
pub const GL_DEBUG_OUTPUT_KHR: GLenum = 0x92E0;
pub const GL_CONTEXT_FLAG_DEBUG_BIT_KHR: GLenum = 0x00000002;
pub const GL_STACK_OVERFLOW_KHR: GLenum = 0x0503;
pub const GL_STACK_UNDERFLOW_KHR: GLenum = 0x0504;
