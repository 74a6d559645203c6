// SPDX-License-Identifier: Apache-2.0
#include "io/frame_scaler.hpp"

namespace rays::io {

std::optional<FrameScaler> FrameScaler::make(int width, int height, int chroma_w, int chroma_h, Crop crop,
                                             std::string& error) {
    auto luma = AreaScaler::make(width, height, crop, error);
    if (!luma) return std::nullopt;
    FrameScaler scaler(std::move(*luma));
    if (chroma_w > 0) {
        scaler.chroma_ = ChromaScaler::make(width, height, chroma_w, chroma_h, scaler.luma_.crop(), error);
        if (!scaler.chroma_) return std::nullopt;
    }
    return scaler;
}

void FrameScaler::scale(const SourceImage& source, GreyImage& luma, Chroma& chroma) const {
    luma_.scale(source.grey.data(), source.width, luma);
    chroma.present = chroma_.has_value() && source.has_chroma();
    if (chroma.present) chroma_->scale(source.u.data(), source.v.data(), source.chroma_width, chroma);
}

}  // namespace rays::io
