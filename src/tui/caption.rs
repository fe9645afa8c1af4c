//! The caption's rows on the explorer's screen: in a served class or a
//! lesson, how many it takes and what they show (the caption kept with
//! its scene is [`crate::scene::KeptCaption`]).

/// The most rows of a caption shown in a class or a lesson.
pub const MAX_CAPTION_ROWS: usize = 4;

/// The text the caption's rows show: the scene's caption, or while a
/// poll is open (outside a lesson, whose captions are written for their
/// polls) the line that says it waits.
pub fn text(app: &crate::tui::app::App) -> &str {
    if app.class.caption_waits() {
        "(the caption shows after the reveal)"
    } else {
        app.state.caption.as_deref().unwrap_or("")
    }
}

/// The rows the caption region asks for in a served class or a lesson:
/// the lecturer's class line, the step line, the caption wrapped to the
/// width (at most [`MAX_CAPTION_ROWS`]) and the claims line; 0 (the usual
/// rows) outside them, whose screens keep their layout.
pub fn rows(app: &crate::tui::app::App) -> u16 {
    let lines = usize::from(app.class.view.is_some()) + usize::from(app.class.step.is_some());
    if lines == 0 {
        return 0;
    }
    let g = app.theme.glyphs;
    let width = usize::from(app.size.0);
    let caption = crate::tui::wrap::wrap(&g.text(text(app)), width, MAX_CAPTION_ROWS, g.cut());
    (lines + caption.len() + 1) as u16
}
