// softgl/enums.h — OpenGL's symbolic constants, with OpenGL's numeric values.
//
// Every entry point that takes an enum takes a plain `softgl::Enum`, so that a wrong value can be passed and
// reported by GetError() as INVALID_ENUM, exactly as OpenGL does. The numbers are OpenGL's own, which makes
// a scene easy to port between softgl and a real OpenGL implementation.
#pragma once

#include <softgl/config.h>

#include <cstdint>

namespace softgl {

using Enum = std::uint32_t;
using Bitfield = std::uint32_t;

// Errors, as returned by Context::GetError().
inline constexpr Enum NO_ERROR = 0;
inline constexpr Enum INVALID_ENUM = 0x0500;
inline constexpr Enum INVALID_VALUE = 0x0501;
inline constexpr Enum INVALID_OPERATION = 0x0502;
inline constexpr Enum OUT_OF_MEMORY = 0x0505;
inline constexpr Enum INVALID_FRAMEBUFFER_OPERATION = 0x0506;

// Buffer targets and usage hints.
inline constexpr Enum ARRAY_BUFFER = 0x8892;
inline constexpr Enum ELEMENT_ARRAY_BUFFER = 0x8893;
inline constexpr Enum COPY_READ_BUFFER = 0x8F36;   // binding points for CopyBufferSubData (any buffer call takes them)
inline constexpr Enum COPY_WRITE_BUFFER = 0x8F37;
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER = 0x8C8E;  // also indexed: BindBufferBase / BindBufferRange

// MapBufferRange access bits, MapBuffer access, and GetBufferParameter names.
inline constexpr Bitfield MAP_READ_BIT = 0x0001;
inline constexpr Bitfield MAP_WRITE_BIT = 0x0002;
inline constexpr Bitfield MAP_INVALIDATE_RANGE_BIT = 0x0004;
inline constexpr Bitfield MAP_INVALIDATE_BUFFER_BIT = 0x0008;
inline constexpr Bitfield MAP_FLUSH_EXPLICIT_BIT = 0x0010;
inline constexpr Bitfield MAP_UNSYNCHRONIZED_BIT = 0x0020;
inline constexpr Enum READ_ONLY = 0x88B8;
inline constexpr Enum WRITE_ONLY = 0x88B9;
inline constexpr Enum READ_WRITE = 0x88BA;
inline constexpr Enum BUFFER_SIZE = 0x8764;
inline constexpr Enum BUFFER_USAGE = 0x8765;
inline constexpr Enum BUFFER_ACCESS = 0x88BB;
inline constexpr Enum BUFFER_MAPPED = 0x88BC;
inline constexpr Enum BUFFER_MAP_POINTER = 0x88BD;
inline constexpr Enum BUFFER_ACCESS_FLAGS = 0x911F;
inline constexpr Enum BUFFER_MAP_LENGTH = 0x9120;
inline constexpr Enum BUFFER_MAP_OFFSET = 0x9121;
inline constexpr Enum STREAM_DRAW = 0x88E0;
inline constexpr Enum STREAM_READ = 0x88E1;
inline constexpr Enum STREAM_COPY = 0x88E2;
inline constexpr Enum STATIC_DRAW = 0x88E4;
inline constexpr Enum STATIC_READ = 0x88E5;
inline constexpr Enum STATIC_COPY = 0x88E6;
inline constexpr Enum DYNAMIC_DRAW = 0x88E8;
inline constexpr Enum DYNAMIC_READ = 0x88E9;
inline constexpr Enum DYNAMIC_COPY = 0x88EA;

// Data types (vertex attributes and indices).
inline constexpr Enum BYTE = 0x1400;
inline constexpr Enum UNSIGNED_BYTE = 0x1401;
inline constexpr Enum SHORT = 0x1402;
inline constexpr Enum UNSIGNED_SHORT = 0x1403;
inline constexpr Enum HALF_FLOAT = 0x140B;
inline constexpr Enum INT = 0x1404;
inline constexpr Enum UNSIGNED_INT = 0x1405;
inline constexpr Enum FLOAT = 0x1406;
inline constexpr Enum DOUBLE = 0x140A;  // vertex attributes only (converted to float when fetched)
// Packed vertex attribute types: four components in 32 bits (x in the low 10 bits, then y, z, and w in the top 2).
inline constexpr Enum INT_2_10_10_10_REV = 0x8D9F;
inline constexpr Enum UNSIGNED_INT_2_10_10_10_REV = 0x8368;  // also a packed pixel type (below)

// Primitive modes.
inline constexpr Enum POINTS = 0x0000;
inline constexpr Enum LINES = 0x0001;
inline constexpr Enum LINE_LOOP = 0x0002;
inline constexpr Enum LINE_STRIP = 0x0003;
inline constexpr Enum TRIANGLES = 0x0004;
inline constexpr Enum TRIANGLE_STRIP = 0x0005;
inline constexpr Enum TRIANGLE_FAN = 0x0006;
// With adjacency: each primitive also carries the vertices next to it, which only a geometry stage reads (without
// one they are drawn as LINES, LINE_STRIP, TRIANGLES and TRIANGLE_STRIP, the adjacent vertices ignored).
inline constexpr Enum LINES_ADJACENCY = 0x000A;
inline constexpr Enum LINE_STRIP_ADJACENCY = 0x000B;
inline constexpr Enum TRIANGLES_ADJACENCY = 0x000C;
inline constexpr Enum TRIANGLE_STRIP_ADJACENCY = 0x000D;

// Provoking vertex conventions (ProvokingVertex): which vertex of a primitive gives flat varyings.
inline constexpr Enum FIRST_VERTEX_CONVENTION = 0x8E4D;
inline constexpr Enum LAST_VERTEX_CONVENTION = 0x8E4E;

// Clear bits.
inline constexpr Bitfield DEPTH_BUFFER_BIT = 0x00000100;
inline constexpr Bitfield STENCIL_BUFFER_BIT = 0x00000400;
inline constexpr Bitfield COLOR_BUFFER_BIT = 0x00004000;

// Capabilities for Enable / Disable / IsEnabled.
inline constexpr Enum CULL_FACE = 0x0B44;
inline constexpr Enum DEPTH_TEST = 0x0B71;
inline constexpr Enum PROGRAM_POINT_SIZE = 0x8642;
inline constexpr Enum SCISSOR_TEST = 0x0C11;
inline constexpr Enum STENCIL_TEST = 0x0B90;
inline constexpr Enum BLEND = 0x0BE2;
inline constexpr Enum POLYGON_OFFSET_POINT = 0x2A01;
inline constexpr Enum POLYGON_OFFSET_LINE = 0x2A02;
inline constexpr Enum POLYGON_OFFSET_FILL = 0x8037;
inline constexpr Enum PRIMITIVE_RESTART = 0x8F9D;              // with PrimitiveRestartIndex
inline constexpr Enum PRIMITIVE_RESTART_FIXED_INDEX = 0x8D69;  // 2^N - 1 for N-bit indices
inline constexpr Enum FRAMEBUFFER_SRGB = 0x8DB9;  // sRGB encoding on store (and decoding for blending) into sRGB buffers
inline constexpr Enum MULTISAMPLE = 0x809D;               // per-sample coverage into multisampled buffers (on by default)
inline constexpr Enum SAMPLE_ALPHA_TO_COVERAGE = 0x809E;  // output 0's alpha picks the samples covered
inline constexpr Enum SAMPLE_ALPHA_TO_ONE = 0x809F;       // then every output's alpha becomes 1
inline constexpr Enum SAMPLE_COVERAGE = 0x80A0;           // SampleCoverage's mask
inline constexpr Enum SAMPLE_MASK = 0x8E51;               // SampleMaski's mask
inline constexpr Enum SAMPLE_SHADING = 0x8C36;            // the shader once per sample (MinSampleShading)

// Faces, winding and polygon modes.
inline constexpr Enum FRONT = 0x0404;
inline constexpr Enum BACK = 0x0405;
inline constexpr Enum FRONT_AND_BACK = 0x0408;
inline constexpr Enum CW = 0x0900;
inline constexpr Enum CCW = 0x0901;
inline constexpr Enum POINT = 0x1B00;
inline constexpr Enum LINE = 0x1B01;
inline constexpr Enum FILL = 0x1B02;

// Comparison functions (depth and stencil tests).
inline constexpr Enum NEVER = 0x0200;
inline constexpr Enum LESS = 0x0201;
inline constexpr Enum EQUAL = 0x0202;
inline constexpr Enum LEQUAL = 0x0203;
inline constexpr Enum GREATER = 0x0204;
inline constexpr Enum NOTEQUAL = 0x0205;
inline constexpr Enum GEQUAL = 0x0206;
inline constexpr Enum ALWAYS = 0x0207;

// Stencil operations (ZERO is the blend factor ZERO, 0, as in OpenGL).
inline constexpr Enum KEEP = 0x1E00;
inline constexpr Enum REPLACE = 0x1E01;
inline constexpr Enum INCR = 0x1E02;
inline constexpr Enum DECR = 0x1E03;
inline constexpr Enum INVERT = 0x150A;
inline constexpr Enum INCR_WRAP = 0x8507;
inline constexpr Enum DECR_WRAP = 0x8508;

// Logic operations (LogicOp; INVERT is the stencil operation's enum, as in OpenGL), and their state.
inline constexpr Enum CLEAR = 0x1500;
inline constexpr Enum AND = 0x1501;
inline constexpr Enum AND_REVERSE = 0x1502;
inline constexpr Enum COPY = 0x1503;
inline constexpr Enum AND_INVERTED = 0x1504;
inline constexpr Enum NOOP = 0x1505;
inline constexpr Enum XOR = 0x1506;
inline constexpr Enum OR = 0x1507;
inline constexpr Enum NOR = 0x1508;
inline constexpr Enum EQUIV = 0x1509;
inline constexpr Enum OR_REVERSE = 0x150B;
inline constexpr Enum COPY_INVERTED = 0x150C;
inline constexpr Enum OR_INVERTED = 0x150D;
inline constexpr Enum NAND = 0x150E;
inline constexpr Enum SET = 0x150F;
inline constexpr Enum COLOR_LOGIC_OP = 0x0BF2;
inline constexpr Enum LOGIC_OP_MODE = 0x0BF0;

// Blend factors.
inline constexpr Enum ZERO = 0;
inline constexpr Enum ONE = 1;
inline constexpr Enum SRC_COLOR = 0x0300;
inline constexpr Enum ONE_MINUS_SRC_COLOR = 0x0301;
inline constexpr Enum SRC_ALPHA = 0x0302;
inline constexpr Enum ONE_MINUS_SRC_ALPHA = 0x0303;
inline constexpr Enum DST_ALPHA = 0x0304;
inline constexpr Enum ONE_MINUS_DST_ALPHA = 0x0305;
inline constexpr Enum DST_COLOR = 0x0306;
inline constexpr Enum ONE_MINUS_DST_COLOR = 0x0307;
inline constexpr Enum SRC_ALPHA_SATURATE = 0x0308;
inline constexpr Enum CONSTANT_COLOR = 0x8001;
inline constexpr Enum ONE_MINUS_CONSTANT_COLOR = 0x8002;
inline constexpr Enum CONSTANT_ALPHA = 0x8003;
inline constexpr Enum ONE_MINUS_CONSTANT_ALPHA = 0x8004;

// Blend equations.
inline constexpr Enum FUNC_ADD = 0x8006;
inline constexpr Enum MIN = 0x8007;
inline constexpr Enum MAX = 0x8008;
inline constexpr Enum FUNC_SUBTRACT = 0x800A;
inline constexpr Enum FUNC_REVERSE_SUBTRACT = 0x800B;

// Textures.
inline constexpr Enum NONE = 0;
inline constexpr Enum TEXTURE_2D = 0x0DE1;
inline constexpr Enum TEXTURE_CUBE_MAP = 0x8513;
inline constexpr Enum TEXTURE_2D_ARRAY = 0x8C1A;
inline constexpr Enum TEXTURE_1D = 0x0DE0;
inline constexpr Enum TEXTURE_1D_ARRAY = 0x8C18;
inline constexpr Enum TEXTURE_3D = 0x806F;
inline constexpr Enum TEXTURE_2D_MULTISAMPLE = 0x9100;
inline constexpr Enum TEXTURE_2D_MULTISAMPLE_ARRAY = 0x9102;
// A buffer texture's target (BindTexture, TexBuffer), and the buffer target of BindBuffer: GetIntegerv of it
// names the buffer bound there.
inline constexpr Enum TEXTURE_BUFFER = 0x8C2A;
inline constexpr Enum TEXTURE_CUBE_MAP_POSITIVE_X = 0x8515;
inline constexpr Enum TEXTURE_CUBE_MAP_NEGATIVE_X = 0x8516;
inline constexpr Enum TEXTURE_CUBE_MAP_POSITIVE_Y = 0x8517;
inline constexpr Enum TEXTURE_CUBE_MAP_NEGATIVE_Y = 0x8518;
inline constexpr Enum TEXTURE_CUBE_MAP_POSITIVE_Z = 0x8519;
inline constexpr Enum TEXTURE_CUBE_MAP_NEGATIVE_Z = 0x851A;
inline constexpr Enum TEXTURE0 = 0x84C0;  // TEXTURE0 + i selects unit i

// Pixel formats (format argument) and internal formats.
inline constexpr Enum STENCIL_INDEX = 0x1901;
inline constexpr Enum DEPTH_COMPONENT = 0x1902;
inline constexpr Enum RED = 0x1903;
inline constexpr Enum GREEN = 0x1904;
inline constexpr Enum BLUE = 0x1905;
inline constexpr Enum BGR = 0x80E0;
inline constexpr Enum BGRA = 0x80E1;
inline constexpr Enum DEPTH_STENCIL = 0x84F9;  // (also ClearBufferfi's buffer)
// ClearBuffer*'s buffers (with DEPTH_STENCIL).
inline constexpr Enum COLOR = 0x1800;
inline constexpr Enum DEPTH = 0x1801;
inline constexpr Enum STENCIL = 0x1802;
inline constexpr Enum UNSIGNED_INT_24_8 = 0x84FA;  // DEPTH_STENCIL pixels: depth in the high 24 bits, stencil low
inline constexpr Enum RGB = 0x1907;
inline constexpr Enum RGBA = 0x1908;
inline constexpr Enum RG = 0x8227;
inline constexpr Enum R8 = 0x8229;
inline constexpr Enum RG8 = 0x822B;
inline constexpr Enum RGB8 = 0x8051;
inline constexpr Enum RGBA8 = 0x8058;
inline constexpr Enum RGB565 = 0x8D62;   // 16 bits a texel: red and blue 5 bits, green 6
inline constexpr Enum RGBA4 = 0x8056;    // 16 bits a texel: 4 a channel
inline constexpr Enum RGB5_A1 = 0x8057;  // 16 bits a texel: 5 a colour channel, alpha 1
inline constexpr Enum RGB10_A2 = 0x8059;  // 32 bits a texel: 10 a colour channel, alpha 2
inline constexpr Enum R16 = 0x822A;      // 16-bit normalized channels: k / 65535
inline constexpr Enum RG16 = 0x822C;
inline constexpr Enum RGBA16 = 0x805B;
inline constexpr Enum R32F = 0x822E;
inline constexpr Enum RGBA32F = 0x8814;
inline constexpr Enum RG32F = 0x8230;
inline constexpr Enum RGBA16F = 0x881A;  // half floats (IEEE binary16), 8 bytes a texel
inline constexpr Enum RG16F = 0x822F;
inline constexpr Enum R16F = 0x822D;
inline constexpr Enum R11F_G11F_B10F = 0x8C3A;  // unsigned 11-, 11- and 10-bit floats packed in 32 bits
// Integer formats (OpenGL 3.3, table 3.12): 8-, 16- or 32-bit integers a channel, unsigned (UI) or signed (I),
// sampled without filtering and read as integers (the shader's ITexture, ITexelFetch ...; see docs/guide.md,
// "Integer textures and colour buffers"). The R, RG and RGBA ones and RGB10_A2UI are colour-renderable; the RGB
// ones are textures only.
inline constexpr Enum R8I = 0x8231;
inline constexpr Enum R8UI = 0x8232;
inline constexpr Enum R16I = 0x8233;
inline constexpr Enum R16UI = 0x8234;
inline constexpr Enum R32I = 0x8235;
inline constexpr Enum R32UI = 0x8236;
inline constexpr Enum RG8I = 0x8237;
inline constexpr Enum RG8UI = 0x8238;
inline constexpr Enum RG16I = 0x8239;
inline constexpr Enum RG16UI = 0x823A;
inline constexpr Enum RG32I = 0x823B;
inline constexpr Enum RG32UI = 0x823C;
inline constexpr Enum RGBA32UI = 0x8D70;
inline constexpr Enum RGB32UI = 0x8D71;
inline constexpr Enum RGBA16UI = 0x8D76;
inline constexpr Enum RGB16UI = 0x8D77;
inline constexpr Enum RGBA8UI = 0x8D7C;
inline constexpr Enum RGB8UI = 0x8D7D;
inline constexpr Enum RGBA32I = 0x8D82;
inline constexpr Enum RGB32I = 0x8D83;
inline constexpr Enum RGBA16I = 0x8D88;
inline constexpr Enum RGB16I = 0x8D89;
inline constexpr Enum RGBA8I = 0x8D8E;
inline constexpr Enum RGB8I = 0x8D8F;
inline constexpr Enum RGB10_A2UI = 0x906F;  // 10 bits a colour channel, alpha 2, unsigned integers
inline constexpr Enum SRGB = 0x8C40;          // FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING's value for sRGB buffers
inline constexpr Enum SRGB8 = 0x8C41;         // sRGB-encoded RGB, 8 bits a channel (alpha reads 1)
inline constexpr Enum SRGB8_ALPHA8 = 0x8C43;  // sRGB-encoded RGB with linear alpha, 8 bits a channel
// Compressed formats: 4 x 4 blocks of texels, 8 or 16 bytes a block, defined by CompressedTexImage1D/2D/3D (see
// docs/guide.md, "Compressed textures"). RGTC (OpenGL 3.0): one or two channels, unsigned or signed. S3TC
// (EXT_texture_compression_s3tc, with EXT_texture_sRGB's sRGB forms): DXT1 (BC1) with or without its one-bit alpha,
// DXT3 (BC2) and DXT5 (BC3). BPTC (ARB_texture_compression_bptc, core in OpenGL 4.2): BC7's RGBA, linear or sRGB,
// and BC6H's RGB half floats, signed or unsigned.
inline constexpr Enum COMPRESSED_RGBA_BPTC_UNORM = 0x8E8C;
inline constexpr Enum COMPRESSED_SRGB_ALPHA_BPTC_UNORM = 0x8E8D;
inline constexpr Enum COMPRESSED_RGB_BPTC_SIGNED_FLOAT = 0x8E8E;    // BC6H: RGB half floats, signed
inline constexpr Enum COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT = 0x8E8F;  // BC6H: RGB half floats, not below 0
inline constexpr Enum COMPRESSED_RED_RGTC1 = 0x8DBB;
inline constexpr Enum COMPRESSED_SIGNED_RED_RGTC1 = 0x8DBC;
inline constexpr Enum COMPRESSED_RG_RGTC2 = 0x8DBD;
inline constexpr Enum COMPRESSED_SIGNED_RG_RGTC2 = 0x8DBE;
inline constexpr Enum COMPRESSED_RGB_S3TC_DXT1_EXT = 0x83F0;
inline constexpr Enum COMPRESSED_RGBA_S3TC_DXT1_EXT = 0x83F1;
inline constexpr Enum COMPRESSED_RGBA_S3TC_DXT3_EXT = 0x83F2;
inline constexpr Enum COMPRESSED_RGBA_S3TC_DXT5_EXT = 0x83F3;
inline constexpr Enum COMPRESSED_SRGB_S3TC_DXT1_EXT = 0x8C4C;
inline constexpr Enum COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT = 0x8C4D;
inline constexpr Enum COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT = 0x8C4E;
inline constexpr Enum COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT = 0x8C4F;
// OpenGL's generic compressed formats, which TexImage* accepts and softgl stores uncompressed (as OpenGL allows):
// as R8, RG8, RGB8, RGBA8, SRGB8 and SRGB8_ALPHA8.
inline constexpr Enum COMPRESSED_RED = 0x8225;
inline constexpr Enum COMPRESSED_RG = 0x8226;
inline constexpr Enum COMPRESSED_RGB = 0x84ED;
inline constexpr Enum COMPRESSED_RGBA = 0x84EE;
inline constexpr Enum COMPRESSED_SRGB = 0x8C48;
inline constexpr Enum COMPRESSED_SRGB_ALPHA = 0x8C49;
inline constexpr Enum DEPTH_COMPONENT16 = 0x81A5;  // 16-bit fixed point (k / 65535); the other depth formats float
inline constexpr Enum DEPTH_COMPONENT24 = 0x81A6;
inline constexpr Enum DEPTH_COMPONENT32F = 0x8CAC;
inline constexpr Enum DEPTH24_STENCIL8 = 0x88F0;
inline constexpr Enum DEPTH32F_STENCIL8 = 0x8CAD;
inline constexpr Enum STENCIL_INDEX8 = 0x8D48;  // renderbuffers only
// Renderbuffer formats OpenGL 3.3 accepts without requiring their sizes: stored as DEPTH_COMPONENT24 and
// STENCIL_INDEX8 (RENDERBUFFER_DEPTH_SIZE and _STENCIL_SIZE report what is stored).
inline constexpr Enum DEPTH_COMPONENT32 = 0x81A7;
inline constexpr Enum STENCIL_INDEX1 = 0x8D46;
inline constexpr Enum STENCIL_INDEX4 = 0x8D47;
inline constexpr Enum STENCIL_INDEX16 = 0x8D49;
inline constexpr Enum FLOAT_32_UNSIGNED_INT_24_8_REV = 0x8DAD;  // DEPTH_STENCIL pixels: a float, then stencil low
// Integer pixel formats: client data of the integer textures and colour buffers (TexImage*, ReadPixels,
// GetTexImage), with integer types only; a transfer between integer data and a non-integer format (or the reverse)
// is answered INVALID_OPERATION.
inline constexpr Enum RED_INTEGER = 0x8D94;
inline constexpr Enum GREEN_INTEGER = 0x8D95;
inline constexpr Enum BLUE_INTEGER = 0x8D96;
inline constexpr Enum RG_INTEGER = 0x8228;
inline constexpr Enum RGB_INTEGER = 0x8D98;
inline constexpr Enum RGBA_INTEGER = 0x8D99;
inline constexpr Enum BGR_INTEGER = 0x8D9A;
inline constexpr Enum BGRA_INTEGER = 0x8D9B;
// Packed pixel types (OpenGL 3.3, table 3.5): all of a pixel's components in one 8-, 16- or 32-bit value, the first
// component in the highest bits, or with _REV in the lowest. 3_3_2 and 5_6_5 hold RGB; the others RGBA or BGRA;
// UNSIGNED_INT_10F_11F_11F_REV (unsigned small floats) and UNSIGNED_INT_5_9_9_9_REV (three 9-bit mantissas sharing
// a 5-bit exponent) hold RGB.
inline constexpr Enum UNSIGNED_BYTE_3_3_2 = 0x8032;
inline constexpr Enum UNSIGNED_BYTE_2_3_3_REV = 0x8362;
inline constexpr Enum UNSIGNED_SHORT_5_6_5 = 0x8363;
inline constexpr Enum UNSIGNED_SHORT_5_6_5_REV = 0x8364;
inline constexpr Enum UNSIGNED_SHORT_4_4_4_4 = 0x8033;
inline constexpr Enum UNSIGNED_SHORT_4_4_4_4_REV = 0x8365;
inline constexpr Enum UNSIGNED_SHORT_5_5_5_1 = 0x8034;
inline constexpr Enum UNSIGNED_SHORT_1_5_5_5_REV = 0x8366;
inline constexpr Enum UNSIGNED_INT_8_8_8_8 = 0x8035;
inline constexpr Enum UNSIGNED_INT_8_8_8_8_REV = 0x8367;
inline constexpr Enum UNSIGNED_INT_10_10_10_2 = 0x8036;
inline constexpr Enum UNSIGNED_INT_10F_11F_11F_REV = 0x8C3B;
inline constexpr Enum UNSIGNED_INT_5_9_9_9_REV = 0x8C3E;

// Texture parameters and their values.
inline constexpr Enum TEXTURE_MAG_FILTER = 0x2800;
inline constexpr Enum TEXTURE_MIN_FILTER = 0x2801;
inline constexpr Enum TEXTURE_WRAP_S = 0x2802;
inline constexpr Enum TEXTURE_WRAP_T = 0x2803;
inline constexpr Enum TEXTURE_WRAP_R = 0x8072;
inline constexpr Enum TEXTURE_BORDER_COLOR = 0x1004;
inline constexpr Enum TEXTURE_MIN_LOD = 0x813A;
inline constexpr Enum TEXTURE_MAX_LOD = 0x813B;
inline constexpr Enum TEXTURE_BASE_LEVEL = 0x813C;
inline constexpr Enum TEXTURE_MAX_LEVEL = 0x813D;
inline constexpr Enum TEXTURE_LOD_BIAS = 0x8501;
inline constexpr Enum TEXTURE_MAX_ANISOTROPY = 0x84FE;  // 1 (the default: off) to MAX_TEXTURE_MAX_ANISOTROPY
inline constexpr Enum TEXTURE_COMPARE_MODE = 0x884C;
inline constexpr Enum TEXTURE_COMPARE_FUNC = 0x884D;
inline constexpr Enum COMPARE_REF_TO_TEXTURE = 0x884E;
inline constexpr Enum TEXTURE_WIDTH = 0x1000;  // GetTexLevelParameter
inline constexpr Enum TEXTURE_HEIGHT = 0x1001;
inline constexpr Enum TEXTURE_DEPTH = 0x8071;
inline constexpr Enum TEXTURE_SAMPLES = 0x9106;
inline constexpr Enum TEXTURE_FIXED_SAMPLE_LOCATIONS = 0x9107;
inline constexpr Enum TEXTURE_INTERNAL_FORMAT = 0x1003;
inline constexpr Enum TEXTURE_RED_SIZE = 0x805C;
inline constexpr Enum TEXTURE_GREEN_SIZE = 0x805D;
inline constexpr Enum TEXTURE_BLUE_SIZE = 0x805E;
inline constexpr Enum TEXTURE_ALPHA_SIZE = 0x805F;
inline constexpr Enum TEXTURE_DEPTH_SIZE = 0x884A;
inline constexpr Enum TEXTURE_STENCIL_SIZE = 0x88F1;
inline constexpr Enum TEXTURE_COMPRESSED = 0x86A1;             // a level of a compressed format
inline constexpr Enum TEXTURE_COMPRESSED_IMAGE_SIZE = 0x86A0;  // its bytes, as GetCompressedTexImage writes them
inline constexpr Enum NEAREST = 0x2600;
inline constexpr Enum LINEAR = 0x2601;
inline constexpr Enum NEAREST_MIPMAP_NEAREST = 0x2700;
inline constexpr Enum LINEAR_MIPMAP_NEAREST = 0x2701;
inline constexpr Enum NEAREST_MIPMAP_LINEAR = 0x2702;
inline constexpr Enum LINEAR_MIPMAP_LINEAR = 0x2703;
inline constexpr Enum REPEAT = 0x2901;
inline constexpr Enum CLAMP_TO_BORDER = 0x812D;
inline constexpr Enum CLAMP_TO_EDGE = 0x812F;
inline constexpr Enum MIRRORED_REPEAT = 0x8370;
// PixelStore's parameters (OpenGL 3.3, tables 3.1 and 4.5).
inline constexpr Enum UNPACK_SWAP_BYTES = 0x0CF0;
inline constexpr Enum UNPACK_LSB_FIRST = 0x0CF1;
inline constexpr Enum UNPACK_ROW_LENGTH = 0x0CF2;
inline constexpr Enum UNPACK_SKIP_ROWS = 0x0CF3;
inline constexpr Enum UNPACK_SKIP_PIXELS = 0x0CF4;
inline constexpr Enum UNPACK_ALIGNMENT = 0x0CF5;
inline constexpr Enum UNPACK_SKIP_IMAGES = 0x806D;
inline constexpr Enum UNPACK_IMAGE_HEIGHT = 0x806E;
inline constexpr Enum PACK_SWAP_BYTES = 0x0D00;
inline constexpr Enum PACK_LSB_FIRST = 0x0D01;
inline constexpr Enum PACK_ROW_LENGTH = 0x0D02;
inline constexpr Enum PACK_SKIP_ROWS = 0x0D03;
inline constexpr Enum PACK_SKIP_PIXELS = 0x0D04;
inline constexpr Enum PACK_ALIGNMENT = 0x0D05;
inline constexpr Enum PACK_SKIP_IMAGES = 0x806B;
inline constexpr Enum PACK_IMAGE_HEIGHT = 0x806C;

// Framebuffer objects.
inline constexpr Enum FRAMEBUFFER = 0x8D40;
inline constexpr Enum READ_FRAMEBUFFER = 0x8CA8;
inline constexpr Enum DRAW_FRAMEBUFFER = 0x8CA9;
inline constexpr Enum COLOR_ATTACHMENT0 = 0x8CE0;  // COLOR_ATTACHMENT0 + i
inline constexpr Enum DEPTH_ATTACHMENT = 0x8D00;
inline constexpr Enum STENCIL_ATTACHMENT = 0x8D20;
inline constexpr Enum DEPTH_STENCIL_ATTACHMENT = 0x821A;  // both DEPTH_ATTACHMENT and STENCIL_ATTACHMENT
inline constexpr Enum FRAMEBUFFER_COMPLETE = 0x8CD5;
inline constexpr Enum FRAMEBUFFER_INCOMPLETE_ATTACHMENT = 0x8CD6;
inline constexpr Enum FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT = 0x8CD7;
inline constexpr Enum FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER = 0x8CDB;
inline constexpr Enum FRAMEBUFFER_INCOMPLETE_MULTISAMPLE = 0x8D56;
inline constexpr Enum FRAMEBUFFER_UNSUPPORTED = 0x8CDD;
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE = 0x8CD0;  // GetFramebufferAttachmentParameteriv
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_OBJECT_NAME = 0x8CD1;
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL = 0x8CD2;
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE = 0x8CD3;
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER = 0x8CD4;
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING = 0x8210;  // LINEAR or SRGB
inline constexpr Enum FRAMEBUFFER_ATTACHMENT_LAYERED = 0x8DA7;  // whether FramebufferTexture attached every layer
inline constexpr Enum FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS = 0x8DA8;
inline constexpr Enum TEXTURE = 0x1702;  // an attachment's object type (or NONE, RENDERBUFFER)

// Renderbuffers.
inline constexpr Enum RENDERBUFFER = 0x8D41;
inline constexpr Enum RENDERBUFFER_WIDTH = 0x8D42;  // GetRenderbufferParameteriv
inline constexpr Enum RENDERBUFFER_HEIGHT = 0x8D43;
inline constexpr Enum RENDERBUFFER_INTERNAL_FORMAT = 0x8D44;
inline constexpr Enum RENDERBUFFER_RED_SIZE = 0x8D50;
inline constexpr Enum RENDERBUFFER_GREEN_SIZE = 0x8D51;
inline constexpr Enum RENDERBUFFER_BLUE_SIZE = 0x8D52;
inline constexpr Enum RENDERBUFFER_ALPHA_SIZE = 0x8D53;
inline constexpr Enum RENDERBUFFER_DEPTH_SIZE = 0x8D54;
inline constexpr Enum RENDERBUFFER_STENCIL_SIZE = 0x8D55;
inline constexpr Enum RENDERBUFFER_SAMPLES = 0x8CAB;

// Colour buffers of the default framebuffer (ReadBuffer): it has one, which all of these name but the RIGHT ones.
inline constexpr Enum FRONT_LEFT = 0x0400;
inline constexpr Enum FRONT_RIGHT = 0x0401;
inline constexpr Enum BACK_LEFT = 0x0402;
inline constexpr Enum BACK_RIGHT = 0x0403;
inline constexpr Enum LEFT = 0x0406;
inline constexpr Enum RIGHT = 0x0407;

// State queries (GetIntegerv, GetFloatv, GetBooleanv, GetInteger64v) and GetString.
inline constexpr Enum ARRAY_BUFFER_BINDING = 0x8894;
inline constexpr Enum ELEMENT_ARRAY_BUFFER_BINDING = 0x8895;
inline constexpr Enum COPY_READ_BUFFER_BINDING = 0x8F36;   // the same value as COPY_READ_BUFFER
inline constexpr Enum COPY_WRITE_BUFFER_BINDING = 0x8F37;  // the same value as COPY_WRITE_BUFFER
inline constexpr Enum VERTEX_ARRAY_BINDING = 0x85B5;
inline constexpr Enum ACTIVE_TEXTURE = 0x84E0;
inline constexpr Enum TEXTURE_BINDING_2D = 0x8069;
inline constexpr Enum TEXTURE_BINDING_CUBE_MAP = 0x8514;
inline constexpr Enum TEXTURE_BINDING_2D_ARRAY = 0x8C1D;
inline constexpr Enum TEXTURE_BINDING_3D = 0x806A;
inline constexpr Enum TEXTURE_BINDING_1D = 0x8068;
inline constexpr Enum TEXTURE_BINDING_1D_ARRAY = 0x8C1C;
inline constexpr Enum TEXTURE_BINDING_BUFFER = 0x8C2C;
// GetTexLevelParameter of a buffer texture: the buffer whose store holds its texels (0: none).
inline constexpr Enum TEXTURE_BUFFER_DATA_STORE_BINDING = 0x8C2D;
// GetVertexAttrib* (VERTEX_ATTRIB_ARRAY_DIVISOR and the others an attribute array has).
inline constexpr Enum VERTEX_ATTRIB_ARRAY_ENABLED = 0x8622;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_SIZE = 0x8623;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_STRIDE = 0x8624;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_TYPE = 0x8625;
inline constexpr Enum CURRENT_VERTEX_ATTRIB = 0x8626;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_POINTER = 0x8645;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_NORMALIZED = 0x886A;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_BUFFER_BINDING = 0x889F;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_INTEGER = 0x88FD;
inline constexpr Enum VERTEX_ATTRIB_ARRAY_DIVISOR = 0x88FE;
inline constexpr Enum SAMPLER_BINDING = 0x8919;  // GetIntegerv: the sampler object bound to the active unit
inline constexpr Enum TEXTURE_BINDING_2D_MULTISAMPLE = 0x9104;
inline constexpr Enum TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY = 0x9105;
inline constexpr Enum DRAW_FRAMEBUFFER_BINDING = 0x8CA6;  // also FRAMEBUFFER_BINDING
inline constexpr Enum READ_FRAMEBUFFER_BINDING = 0x8CAA;
inline constexpr Enum DRAW_BUFFER0 = 0x8825;  // DRAW_BUFFER0 + i
inline constexpr Enum DRAW_BUFFER = 0x0C01;   // the same as DRAW_BUFFER0
inline constexpr Enum READ_BUFFER = 0x0C02;
inline constexpr Enum RENDERBUFFER_BINDING = 0x8CA7;
inline constexpr Enum MAX_RENDERBUFFER_SIZE = 0x84E8;
inline constexpr Enum VIEWPORT = 0x0BA2;
inline constexpr Enum DEPTH_RANGE = 0x0B70;
inline constexpr Enum SCISSOR_BOX = 0x0C10;
inline constexpr Enum CULL_FACE_MODE = 0x0B45;
inline constexpr Enum FRONT_FACE = 0x0B46;
inline constexpr Enum POLYGON_MODE = 0x0B40;
inline constexpr Enum POINT_SIZE = 0x0B11;
// PointParameter's names and POINT_SPRITE_COORD_ORIGIN's values.
inline constexpr Enum POINT_FADE_THRESHOLD_SIZE = 0x8128;
inline constexpr Enum POINT_SPRITE_COORD_ORIGIN = 0x8CA0;
inline constexpr Enum LOWER_LEFT = 0x8CA1;
inline constexpr Enum UPPER_LEFT = 0x8CA2;
inline constexpr Enum PROVOKING_VERTEX = 0x8E4F;
inline constexpr Enum POLYGON_OFFSET_FACTOR = 0x8038;
inline constexpr Enum POLYGON_OFFSET_UNITS = 0x2A00;
inline constexpr Enum PRIMITIVE_RESTART_INDEX = 0x8F9E;
inline constexpr Enum DEPTH_FUNC = 0x0B74;
inline constexpr Enum DEPTH_WRITEMASK = 0x0B72;
inline constexpr Enum DEPTH_CLEAR_VALUE = 0x0B73;
inline constexpr Enum STENCIL_FUNC = 0x0B92;
inline constexpr Enum STENCIL_VALUE_MASK = 0x0B93;
inline constexpr Enum STENCIL_FAIL = 0x0B94;
inline constexpr Enum STENCIL_PASS_DEPTH_FAIL = 0x0B95;
inline constexpr Enum STENCIL_PASS_DEPTH_PASS = 0x0B96;
inline constexpr Enum STENCIL_REF = 0x0B97;
inline constexpr Enum STENCIL_WRITEMASK = 0x0B98;
inline constexpr Enum STENCIL_CLEAR_VALUE = 0x0B91;
inline constexpr Enum STENCIL_BACK_FUNC = 0x8800;
inline constexpr Enum STENCIL_BACK_FAIL = 0x8801;
inline constexpr Enum STENCIL_BACK_PASS_DEPTH_FAIL = 0x8802;
inline constexpr Enum STENCIL_BACK_PASS_DEPTH_PASS = 0x8803;
inline constexpr Enum STENCIL_BACK_REF = 0x8CA3;
inline constexpr Enum STENCIL_BACK_VALUE_MASK = 0x8CA4;
inline constexpr Enum STENCIL_BACK_WRITEMASK = 0x8CA5;
inline constexpr Enum BLEND_DST_RGB = 0x80C8;
inline constexpr Enum BLEND_SRC_RGB = 0x80C9;
inline constexpr Enum BLEND_DST_ALPHA = 0x80CA;
inline constexpr Enum BLEND_SRC_ALPHA = 0x80CB;
inline constexpr Enum BLEND_EQUATION_RGB = 0x8009;
inline constexpr Enum BLEND_EQUATION_ALPHA = 0x883D;
inline constexpr Enum BLEND_COLOR = 0x8005;
inline constexpr Enum COLOR_CLEAR_VALUE = 0x0C22;
inline constexpr Enum COLOR_WRITEMASK = 0x0C23;
inline constexpr Enum MAX_VERTEX_ATTRIBS = 0x8869;
inline constexpr Enum MAX_TEXTURE_SIZE = 0x0D33;
inline constexpr Enum MAX_TEXTURE_BUFFER_SIZE = 0x8C2B;  // kMaxTextureBufferSize
inline constexpr Enum MAX_CUBE_MAP_TEXTURE_SIZE = 0x851C;
inline constexpr Enum MAX_3D_TEXTURE_SIZE = 0x8073;
inline constexpr Enum MAX_ARRAY_TEXTURE_LAYERS = 0x88FF;
inline constexpr Enum MAX_TEXTURE_IMAGE_UNITS = 0x8872;
inline constexpr Enum MAX_VERTEX_TEXTURE_IMAGE_UNITS = 0x8B4C;
inline constexpr Enum MAX_COMBINED_TEXTURE_IMAGE_UNITS = 0x8B4D;
inline constexpr Enum MAX_DRAW_BUFFERS = 0x8824;
inline constexpr Enum MAX_COLOR_ATTACHMENTS = 0x8CDF;
inline constexpr Enum MAX_SAMPLES = 0x8D57;
inline constexpr Enum MAX_COLOR_TEXTURE_SAMPLES = 0x910E;
inline constexpr Enum MAX_DEPTH_TEXTURE_SAMPLES = 0x910F;
inline constexpr Enum MAX_INTEGER_SAMPLES = 0x9110;  // GetIntegerv: 1, integer images are single-sampled
inline constexpr Enum SAMPLE_BUFFERS = 0x80A8;          // 1 when the draw framebuffer is multisampled, else 0
inline constexpr Enum SAMPLES = 0x80A9;                 // the draw framebuffer's samples per pixel (0: single)
inline constexpr Enum SAMPLE_COVERAGE_VALUE = 0x80AA;
inline constexpr Enum SAMPLE_COVERAGE_INVERT = 0x80AB;
inline constexpr Enum MIN_SAMPLE_SHADING_VALUE = 0x8C37;  // MinSampleShading's value
inline constexpr Enum SAMPLE_MASK_VALUE = 0x8E52;       // word 0 of the sample mask
inline constexpr Enum MAX_SAMPLE_MASK_WORDS = 0x8E59;
inline constexpr Enum SAMPLE_POSITION = 0x8E50;         // GetMultisamplefv
inline constexpr Enum MAX_TEXTURE_MAX_ANISOTROPY = 0x84FF;  // 16
inline constexpr Enum MAX_VIEWPORT_DIMS = 0x0D3A;
inline constexpr Enum NUM_COMPRESSED_TEXTURE_FORMATS = 0x86A2;  // 4: the S3TC formats (RGTC's are not listed, as OpenGL says)
inline constexpr Enum COMPRESSED_TEXTURE_FORMATS = 0x86A3;
inline constexpr Enum MAX_VARYING_COMPONENTS = 0x8B4B;
inline constexpr Enum MAX_GEOMETRY_OUTPUT_VERTICES = 0x8DE0;
inline constexpr Enum MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS = 0x8DE1;
inline constexpr Enum MAX_GEOMETRY_SHADER_INVOCATIONS = 0x8E5A;
inline constexpr Enum MAX_GEOMETRY_INPUT_COMPONENTS = 0x9123;
inline constexpr Enum MAX_GEOMETRY_OUTPUT_COMPONENTS = 0x9124;
inline constexpr Enum MAX_ELEMENTS_VERTICES = 0x80E8;
inline constexpr Enum MAX_ELEMENTS_INDICES = 0x80E9;
inline constexpr Enum POINT_SIZE_RANGE = 0x0B12;
inline constexpr Enum ALIASED_LINE_WIDTH_RANGE = 0x846E;
inline constexpr Enum LINE_WIDTH = 0x0B21;
inline constexpr Enum SUBPIXEL_BITS = 0x0D50;
inline constexpr Enum MAJOR_VERSION = 0x821B;
inline constexpr Enum MINOR_VERSION = 0x821C;
inline constexpr Enum NUM_EXTENSIONS = 0x821D;
inline constexpr Enum CONTEXT_PROFILE_MASK = 0x9126;
inline constexpr Enum VENDOR = 0x1F00;
inline constexpr Enum RENDERER = 0x1F01;
inline constexpr Enum VERSION = 0x1F02;
inline constexpr Enum SHADING_LANGUAGE_VERSION = 0x8B8C;

// Queries.
inline constexpr Enum SAMPLES_PASSED = 0x8914;
inline constexpr Enum ANY_SAMPLES_PASSED = 0x8C2F;
inline constexpr Enum PRIMITIVES_GENERATED = 0x8C87;
inline constexpr Enum TIME_ELAPSED = 0x88BF;
inline constexpr Enum TIMESTAMP = 0x8E28;  // QueryCounter's target; GetInteger64v: the time now, in nanoseconds
inline constexpr Enum QUERY_COUNTER_BITS = 0x8864;
inline constexpr Enum CURRENT_QUERY = 0x8865;
inline constexpr Enum QUERY_RESULT = 0x8866;
inline constexpr Enum QUERY_RESULT_AVAILABLE = 0x8867;

// Transform feedback (BeginTransformFeedback, TransformFeedbackVaryings, the queries of its state).
inline constexpr Enum TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN = 0x8C88;  // a query target
inline constexpr Enum RASTERIZER_DISCARD = 0x8C89;                     // an Enable capability
inline constexpr Enum INTERLEAVED_ATTRIBS = 0x8C8C;
inline constexpr Enum SEPARATE_ATTRIBS = 0x8C8D;
inline constexpr Enum TRANSFORM_FEEDBACK = 0x8E22;  // BindTransformFeedback's target
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER_START = 0x8C84;
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER_SIZE = 0x8C85;
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER_BINDING = 0x8C8F;
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER_PAUSED = 0x8E23;  // (TRANSFORM_FEEDBACK_PAUSED)
inline constexpr Enum TRANSFORM_FEEDBACK_BUFFER_ACTIVE = 0x8E24;  // (TRANSFORM_FEEDBACK_ACTIVE)
inline constexpr Enum TRANSFORM_FEEDBACK_BINDING = 0x8E25;
inline constexpr Enum MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS = 0x8C8A;
inline constexpr Enum MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS = 0x8C8B;
inline constexpr Enum MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS = 0x8C80;
inline constexpr Enum MAX_TRANSFORM_FEEDBACK_BUFFERS = 0x8E70;
inline constexpr Enum FLOAT_VEC2 = 0x8B50;  // GetTransformFeedbackVarying's types (and FLOAT)
inline constexpr Enum FLOAT_VEC3 = 0x8B51;
inline constexpr Enum FLOAT_VEC4 = 0x8B52;

// Conditional rendering (BeginConditionalRender's modes).
inline constexpr Enum QUERY_WAIT = 0x8E13;
inline constexpr Enum QUERY_NO_WAIT = 0x8E14;
inline constexpr Enum QUERY_BY_REGION_WAIT = 0x8E15;
inline constexpr Enum QUERY_BY_REGION_NO_WAIT = 0x8E16;

// Sync objects (FenceSync, ClientWaitSync, WaitSync, GetSynciv).
inline constexpr Enum SYNC_GPU_COMMANDS_COMPLETE = 0x9117;
inline constexpr Bitfield SYNC_FLUSH_COMMANDS_BIT = 0x00000001;
inline constexpr std::uint64_t TIMEOUT_IGNORED = 0xFFFFFFFFFFFFFFFFull;
inline constexpr Enum MAX_SERVER_WAIT_TIMEOUT = 0x9111;
inline constexpr Enum OBJECT_TYPE = 0x9112;
inline constexpr Enum SYNC_CONDITION = 0x9113;
inline constexpr Enum SYNC_STATUS = 0x9114;
inline constexpr Enum SYNC_FLAGS = 0x9115;
inline constexpr Enum SYNC_FENCE = 0x9116;
inline constexpr Enum UNSIGNALED = 0x9118;
inline constexpr Enum SIGNALED = 0x9119;
inline constexpr Enum ALREADY_SIGNALED = 0x911A;
inline constexpr Enum TIMEOUT_EXPIRED = 0x911B;
inline constexpr Enum CONDITION_SATISFIED = 0x911C;
inline constexpr Enum WAIT_FAILED = 0x911D;

// ClampColor (its clamp is also true or false: OpenGL's TRUE and FALSE are 1 and 0).
inline constexpr Enum CLAMP_READ_COLOR = 0x891C;
inline constexpr Enum FIXED_ONLY = 0x891D;

}  // namespace softgl
