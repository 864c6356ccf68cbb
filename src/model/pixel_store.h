// pixel_store.h — the model library's uploads and read-backs with OpenGL's default pixel layout, whatever the
// application has set with PixelStore: the context's settings are saved, reset and put back at the end of the
// scope.
#pragma once

#include <softgl/context.h>

namespace softgl::model_detail {

class DefaultPixelStore {
 public:
  explicit DefaultPixelStore(Context& gl) : gl_(gl) {
    for (int i = 0; i < kCount; ++i) {
      gl_.GetIntegerv(kNames[i], &saved_[i]);
      gl_.PixelStore(kNames[i], kDefaults[i]);
    }
  }
  ~DefaultPixelStore() {
    for (int i = 0; i < kCount; ++i) gl_.PixelStore(kNames[i], saved_[i]);
  }
  DefaultPixelStore(const DefaultPixelStore&) = delete;
  DefaultPixelStore& operator=(const DefaultPixelStore&) = delete;

 private:
  static constexpr int kCount = 14;
  static constexpr Enum kNames[kCount] = {UNPACK_ALIGNMENT, UNPACK_ROW_LENGTH, UNPACK_IMAGE_HEIGHT, UNPACK_SKIP_PIXELS,
                                          UNPACK_SKIP_ROWS, UNPACK_SKIP_IMAGES, UNPACK_SWAP_BYTES, PACK_ALIGNMENT,
                                          PACK_ROW_LENGTH, PACK_IMAGE_HEIGHT, PACK_SKIP_PIXELS, PACK_SKIP_ROWS,
                                          PACK_SKIP_IMAGES, PACK_SWAP_BYTES};
  static constexpr int kDefaults[kCount] = {4, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0, 0};
  Context& gl_;
  int saved_[kCount] = {};
};

}  // namespace softgl::model_detail
