//! The flag of each workflow input that `src/study` names in its messages
//! ([`crate::study::input::Input`], printed as `‹keyword›`): the command line turns the
//! keywords into flags in the errors it prints (`cli::run`) and in the log's notes
//! ([`crate::runs::progress::set_note_filter`]); the design report in the notes it quotes.

use crate::study::input::Input;

/// The flag that sets `i` on the command line.
pub fn flag(i: Input) -> &'static str {
    match i {
        Input::Theta => "--theta-deg",
        Input::Alpha => "--alpha-deg",
        Input::LoadMn => "--load-mn",
        Input::LineDeg => "--line-deg",
        Input::Grid => "--grid",
        Input::DistanceUm => "--distance-um",
        Input::StepUm => "--step-um",
        Input::ThetaStepDeg => "--theta-step-deg",
        Input::Solver => "--solver",
        Input::OutDir => "--out-dir",
        Input::Shard => "--shard",
        Input::Resume => "--resume",
        Input::Family => "--family",
        Input::Patterns => "--patterns",
        Input::MaxPq => "--max-pq",
        Input::NoSymmetryCut => "--no-symmetry-cut",
        Input::Tilt => "--tilt",
    }
}

/// `text` with every `‹keyword›` of an [`Input`] replaced by `` `--flag` ``. O(inputs ×
/// length).
pub fn to_flags(text: &str) -> String {
    let mut out = text.to_string();
    for i in Input::ALL {
        let k = i.to_string();
        if out.contains(&k) {
            out = out.replace(&k, &format!("`{}`", flag(i)));
        }
    }
    out
}

/// `e` with its inputs named by their flags (see [`to_flags`]); `e` itself when it names none
/// (so that its cause chain, e.g. a broken pipe, stays inspectable).
pub fn error_with_flags(e: anyhow::Error) -> anyhow::Error {
    let text = format!("{e:#}");
    let mapped = to_flags(&text);
    if mapped == text {
        e
    } else {
        anyhow::anyhow!(mapped)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords_turn_into_flags() {
        assert_eq!(
            to_flags(&format!("{} × {}", Input::Theta, Input::LoadMn)),
            "`--theta-deg` × `--load-mn`"
        );
        assert_eq!(to_flags("`theta` stays"), "`theta` stays");
    }
}
