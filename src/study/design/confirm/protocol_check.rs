//! The study-protocol check's design and load ([`protocol_check_design`]): where a shorter
//! confirmation protocol is measured against the study's.

use crate::study::design::model::{rank, Answer, Check, PatternResult};
use crate::study::load::Load;
use std::cmp::Ordering;

/// The design and load of the study-protocol check: the answer of the best pattern (ranked by
/// its rank-1 design, [`rank::compare`]) whose answer the DEM confirmed (else the best
/// pattern's answer: the report says it is not confirmed), at the middle of its design-protocol runs up to its superlubric load (the
/// confirmed loads), else at the middle confirmation load. So the measured difference is that
/// of the design the report recommends, at a load where the shorter protocol ran on it.
/// `confirm_loads` in N.
pub fn protocol_check_design<'a>(
    patterns: &'a [PatternResult],
    answers: &[Answer],
    confirm_loads: &[f64],
) -> Option<ProtocolCheck<'a>> {
    // the patterns best first, by their rank-1 designs (the ranking's one order), so the
    // design recommended is the one the "Patterns compared" table ranks first
    let mut order: Vec<usize> = (0..patterns.len().min(answers.len())).collect();
    order.sort_by(
        |&a, &b| match (patterns[a].ranking.first(), patterns[b].ranking.first()) {
            (Some(x), Some(y)) => rank::compare(x, y),
            (Some(_), None) => Ordering::Less,
            (None, Some(_)) => Ordering::Greater,
            (None, None) => Ordering::Equal,
        },
    );
    let with_index = || {
        order
            .iter()
            .map(|&k| (&patterns[k], &answers[k]))
            .filter_map(|(pr, a)| a.index.map(|i| (pr, i, a)))
    };
    let (pr, i, a) = with_index()
        .find(|(_, _, a)| matches!(a.check, Check::Confirmed(_)))
        .or_else(|| with_index().next())?;
    let w = match &a.check {
        Check::Confirmed(loads) if !loads.is_empty() => {
            let mn = loads[loads.len() / 2];
            confirm_loads[Load::position(confirm_loads, mn)?]
        }
        _ => *confirm_loads.get(confirm_loads.len() / 2)?,
    };
    Some(ProtocolCheck {
        pattern: pr,
        index: i,
        load: w,
    })
}

/// The design and load of the study-protocol check ([`protocol_check_design`]).
#[derive(Debug, Clone, Copy)]
pub struct ProtocolCheck<'a> {
    /// The pattern.
    pub pattern: &'a PatternResult,
    /// The design: an index into the pattern's ranking.
    pub index: usize,
    /// The load (N).
    pub load: f64,
}
