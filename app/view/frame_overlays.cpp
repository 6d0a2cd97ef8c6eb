#include "app/view/frame_overlays.h"

#include "app/view/strip_chart.h"

namespace tumble::app {

FrameOverlays::FrameOverlays(std::vector<ScreenBox> keep, int width, int height,
                             const OverlayContent& content)
    : layout_(width, height, std::move(keep)) {
    const render::OverlayFont& font = layout_.font();
    using enum Corner;
    if (!content.text.empty()) {
        compact_text_ = layout_.cramped(font.panel_size(content.text));
        const auto& lines = compact_text_ ? content.compact_text : content.text;
        text_at_ =
            layout_.place(font.panel_size(lines), {TopLeft, TopRight, BottomLeft, BottomRight}).min;
    }
    if (!content.legend.empty()) {
        compact_legend_ = layout_.cramped(legend_size(content.legend, font));
        legend_ = compact_legend_ ? content.compact_legend : content.legend;
        legend_box_ =
            layout_.place(legend_size(legend_, font), {TopRight, TopLeft, BottomLeft, BottomRight});
    }
    // The last panel first: stacked upwards from a bottom corner, the first ends on top.
    const glm::vec2 panel = chart_panel_size(font, width, height);
    charts_.resize(content.charts);
    for (std::size_t p = content.charts; p-- > 0;)
        charts_[p] = layout_.place(panel, {BottomRight, BottomLeft, TopRight, TopLeft});
}

void FrameOverlays::draw_legend(render::Canvas& canvas) const {
    if (!legend_.empty()) app::draw_legend(legend_, layout_.font(), legend_box_.min, canvas);
}

} // namespace tumble::app
