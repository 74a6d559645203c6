// SPDX-License-Identifier: Apache-2.0
// A recorded source frame onto the processing frame: the luma's crop to 128×128 (AreaScaler) and,
// when the source has colour, its chroma over the same area to 64×64 (ChromaScaler).
#pragma once
#include <optional>
#include <string>

#include "core/image.hpp"
#include "io/area_scaler.hpp"
#include "io/chroma_scaler.hpp"
#include "io/source_image.hpp"

namespace rays::io {

class FrameScaler {
public:
    // chroma_w = 0: a mono source. nullopt + error when the crop or the chroma planes do not fit.
    static std::optional<FrameScaler> make(int width, int height, int chroma_w, int chroma_h, Crop crop,
                                           std::string& error);

    // `source` must be of the size given to make(). Does not allocate.
    void scale(const SourceImage& source, GreyImage& luma, Chroma& chroma) const;

    const AreaScaler& luma() const { return luma_; }
    bool colour() const { return chroma_.has_value(); }

private:
    explicit FrameScaler(AreaScaler luma) : luma_(std::move(luma)) {}

    AreaScaler luma_;
    std::optional<ChromaScaler> chroma_;
};

}  // namespace rays::io
