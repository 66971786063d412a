//! Cyclic IO data: data types of the DataItems (E309), the configurations
//! of each DAP against its IOConfigData (E310, W302), and the PROFINET
//! frame limit of 1440 bytes (E311).
//!
//! MaxInputLength and MaxOutputLength bound what the input and the output
//! CR carry: the IO data and the status bytes, an IOPS and an IOCS for each
//! submodule (the C_SDU of the frame, whose limit is the 1440 of E311).
//! The schema's attributes bear this out: beside them IOConfigData has
//! MaxApplicationInputLength and MaxApplicationOutputLength, separate
//! "application" lengths with a flag `ApplicationLengthIncludesIOxS`
//! (default false) for whether those count the status bytes. gsdc's
//! emitter writes the same reading (`emit::gsdml::max_io_length`);
//! docs/rules.md, E310, gives the sources and what the corpus does.

use std::collections::BTreeMap;

use foldhash::HashMap;

use super::datatype::{io_size, missing_length, unknown_type, Place, Size};
use super::index::{child, children, describe, in_gsdml, tag_span, value_span, El};
use super::values::{parse_u32, ValueList};
use super::Ctx;
use crate::diag::Diagnostic;

/// The largest C_SDU of a PROFINET RT frame: no IOConfigData may promise more.
const FRAME_LIMIT: u32 = 1440;

/// Bytes of the input and of the output CR: data and status bytes.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
struct Io([u32; 2]);

impl Io {
    fn add(self, other: Io) -> Io {
        Io([
            self.0[0].saturating_add(other.0[0]),
            self.0[1].saturating_add(other.0[1]),
        ])
    }

    fn times(self, n: u32) -> Io {
        Io([self.0[0].saturating_mul(n), self.0[1].saturating_mul(n)])
    }
}

/// (index in `Io`, IOConfigData attribute, direction for messages)
const DIRECTIONS: [(usize, &str, &str); 2] = [
    (0, "MaxInputLength", "input"),
    (1, "MaxOutputLength", "output"),
];

pub fn check(ctx: &Ctx<'_, '_>, out: &mut Vec<Diagnostic>) {
    for item in ctx.idx.all("DataItem").iter().filter(|d| is_io_data(d)) {
        if let Err(diagnostic) = data_item_size(item) {
            out.push(diagnostic);
        }
    }
    let modules: HashMap<&str, Io> = ctx
        .idx
        .all("ModuleItem")
        .iter()
        .filter_map(|m| Some((m.attribute("ID")?, built_in_io(m))))
        .collect();
    for dap in ctx.idx.all("DeviceAccessPointItem") {
        check_dap(dap, &modules, out);
    }
}

fn is_io_data(item: &El<'_, '_>) -> bool {
    item.parent_element()
        .is_some_and(|p| matches!(p.tag_name().name(), "Input" | "Output"))
}

/// Bytes of one DataItem. Missing or malformed attributes count as 0 here;
/// the attribute rules report them.
fn data_item_size(item: &El<'_, '_>) -> Result<u32, Diagnostic> {
    let Some(data_type) = item.attribute("DataType") else {
        return Ok(0);
    };
    match io_size(data_type) {
        Some(Size::Bytes(n)) => Ok(n),
        Some(Size::FromLength) => match item.attribute("Length") {
            Some(length) => Ok(parse_u32(length).unwrap_or(0)),
            None => Err(missing_length(item, data_type)),
        },
        Some(Size::Bits) | None => Err(unknown_type(item, data_type, Place::IoData)),
    }
}

/// What the VirtualSubmoduleItems of a DAP or module add to the CRs: they
/// are always plugged with it.
fn built_in_io(owner: &El<'_, '_>) -> Io {
    let submodules = child(*owner, "VirtualSubmoduleList")
        .into_iter()
        .flat_map(|list| children(list, "VirtualSubmoduleItem"));
    submodules
        .map(|s| submodule_io(&s))
        .fold(Io::default(), Io::add)
}

/// What a DAP always has in the CRs: its virtual submodules, and its
/// interface and port submodules, which carry no data but their status.
fn dap_io(dap: &El<'_, '_>) -> Io {
    let system_defined = child(*dap, "SystemDefinedSubmoduleList")
        .into_iter()
        .flat_map(|list| list.children())
        .filter(in_gsdml);
    system_defined
        .map(|s| submodule_io(&s))
        .fold(built_in_io(dap), Io::add)
}

/// One submodule in the CRs: its data, and its status bytes. A submodule
/// with input data has its IOPS in the input CR and its IOCS in the output
/// CR; one with output data the other way round; one with both has both in
/// each. One without data counts as an input submodule of length 0, as
/// p-net's `pf_cmdev_calculate_exp_sub_data_descriptor_direction` places
/// NO_IO submodules (rtlabs-com/p-net, src/device/pf_cmdev.c).
fn submodule_io(submodule: &El<'_, '_>) -> Io {
    let io_data = child(*submodule, "IOData");
    let data = |direction| {
        let list = io_data.and_then(|d| child(d, direction))?;
        let bytes = children(list, "DataItem")
            .map(|item| data_item_size(&item).unwrap_or(0))
            .fold(0u32, u32::saturating_add);
        Some(bytes)
    };
    let (input, output) = (data("Input"), data("Output"));
    // One status byte in each CR for each direction the submodule has.
    let as_input = u32::from(input.is_some() || output.is_none());
    let status = as_input + u32::from(output.is_some());
    Io([input, output].map(|bytes| bytes.unwrap_or(0).saturating_add(status)))
}

/// A DAP's configurations: the fixed one, each module with it, the largest.
struct Configurations<'a, 'input> {
    fixed: Io,
    /// Every usable module with the fixed configuration, by its reference.
    each: Vec<(El<'a, 'input>, Io)>,
    largest: Io,
}

fn check_dap(dap: &El<'_, '_>, modules: &HashMap<&str, Io>, out: &mut Vec<Diagnostic>) {
    let Some(config) = child(*dap, "IOConfigData") else {
        return;
    };
    for (_, attribute, _) in DIRECTIONS {
        if let Some(max) = config
            .attribute(attribute)
            .and_then(parse_u32)
            .filter(|&m| m > FRAME_LIMIT)
        {
            out.push(
                Diagnostic::error(
                    "E311",
                    format!("{attribute} {max} is more than a PROFINET frame carries"),
                )
                .at(value_span(&config, attribute))
                .label(format!("more than {FRAME_LIMIT}"))
                .help(format!(
                    "IO data of one AR is at most {FRAME_LIMIT} bytes each way; lower {attribute}"
                )),
            );
        }
    }
    let Some(physical) = dap.attribute("PhysicalSlots").and_then(ValueList::parse) else {
        return;
    };
    let configurations = configurations(dap, &physical, modules);
    for direction in DIRECTIONS {
        let Some(max) = config.attribute(direction.1).and_then(parse_u32) else {
            continue;
        };
        check_direction(dap, &config, &configurations, direction, max, out);
    }
}

fn configurations<'a, 'input>(
    dap: &El<'a, 'input>,
    physical: &ValueList,
    modules: &HashMap<&str, Io>,
) -> Configurations<'a, 'input> {
    let dap_io = dap_io(dap);
    let dap_slots = dap.attribute("FixedInSlots").and_then(ValueList::parse);
    let refs: Vec<(El, Io)> = child(*dap, "UseableModules")
        .into_iter()
        .flat_map(|u| children(u, "ModuleItemRef"))
        .filter_map(|r| Some((r, *modules.get(r.attribute("ModuleItemTarget")?)?)))
        .collect();
    let mut fixed = dap_io;
    let mut placements = Vec::with_capacity(refs.len());
    for (reference, io) in &refs {
        if let Some(slots) = reference
            .attribute("FixedInSlots")
            .and_then(ValueList::parse)
        {
            fixed = fixed.add(io.times(slot_count(&slots)));
        }
        let slots = module_slots(reference, physical, dap_slots.as_ref());
        placements.push((slots.intersection(physical), *io));
    }
    let largest = dap_io.add(Io([0, 1].map(|i| sum_of_slot_maxima(&placements, i))));
    let each = refs
        .into_iter()
        .filter(|(r, _)| !r.has_attribute("FixedInSlots"))
        .map(|(r, io)| (r, fixed.add(io)))
        .collect();
    Configurations {
        fixed,
        each,
        largest,
    }
}

/// The sum over all slots of the most bytes (in direction `index`) a
/// module that the slot can take has. A sweep over the range boundaries,
/// so that wide slot ranges cost nothing.
fn sum_of_slot_maxima(placements: &[(ValueList, Io)], index: usize) -> u32 {
    // (position, range ends here, bytes); the end of lo..hi is hi + 1.
    let mut events: Vec<(u64, bool, u32)> = Vec::new();
    for (slots, io) in placements {
        for &(lo, hi) in slots.ranges() {
            events.push((u64::from(lo), false, io.0[index]));
            events.push((u64::from(hi) + 1, true, io.0[index]));
        }
    }
    events.sort_unstable();
    // The bytes of the modules whose ranges cover the current stretch.
    let mut active: BTreeMap<u32, usize> = BTreeMap::new();
    let (mut total, mut previous) = (0u64, 0u64);
    for (position, ends, bytes) in events {
        let most = active.last_key_value().map_or(0, |(b, _)| u64::from(*b));
        total = total.saturating_add((position - previous) * most);
        previous = position;
        if ends {
            if let Some(count) = active.get_mut(&bytes) {
                *count -= 1;
                if *count == 0 {
                    active.remove(&bytes);
                }
            }
        } else {
            *active.entry(bytes).or_default() += 1;
        }
    }
    u32::try_from(total).unwrap_or(u32::MAX)
}

fn slot_count(slots: &ValueList) -> u32 {
    slots
        .ranges()
        .iter()
        .map(|(lo, hi)| (hi - lo).saturating_add(1))
        .fold(0, u32::saturating_add)
}

/// Where a module may go: AllowedInSlots, FixedInSlots and UsedInSlots
/// together; a reference without any of them may go into every physical
/// slot that is not the DAP's.
fn module_slots(
    reference: &El<'_, '_>,
    physical: &ValueList,
    dap_slots: Option<&ValueList>,
) -> ValueList {
    let lists: Vec<&str> = ["AllowedInSlots", "FixedInSlots", "UsedInSlots"]
        .iter()
        .filter_map(|a| reference.attribute(*a))
        .collect();
    if lists.is_empty() {
        return match dap_slots {
            Some(dap) => ValueList::from_ranges(dap.missing_from(physical)),
            None => physical.clone(),
        };
    }
    let ranges = lists
        .into_iter()
        .filter_map(ValueList::parse)
        .flat_map(|l| l.ranges().to_vec());
    ValueList::from_ranges(ranges.collect())
}

fn check_direction(
    dap: &El<'_, '_>,
    config: &El<'_, '_>,
    configurations: &Configurations<'_, '_>,
    (index, attribute, direction): (usize, &str, &str),
    max: u32,
    out: &mut Vec<Diagnostic>,
) {
    let fixed = configurations.fixed.0[index];
    if fixed > max {
        out.push(
            Diagnostic::error(
                "E310",
                format!(
                    "{} and its fixed modules need {fixed} {direction} bytes (status bytes included), more than {attribute}={max}",
                    describe(dap)
                ),
            )
            .at(value_span(config, attribute))
            .label(format!("the fixed configuration needs {fixed}"))
            .help(format!("raise {attribute} to at least {fixed} or make the fixed modules smaller")),
        );
        return;
    }
    let mut too_big = false;
    for (reference, io) in &configurations.each {
        let needed = io.0[index];
        if needed > max {
            too_big = true;
            out.push(
                Diagnostic::error(
                    "E310",
                    format!(
                        "module \"{}\" never fits {}: with the DAP it needs {needed} {direction} bytes (status bytes included), {attribute} is {max}",
                        reference.attribute("ModuleItemTarget").unwrap_or("?"),
                        describe(dap)
                    ),
                )
                .at(tag_span(reference))
                .label(format!("needs {needed} {direction} bytes"))
                .help(format!("raise {attribute} to at least {needed} or remove the module from UseableModules")),
            );
        }
    }
    let largest = configurations.largest.0[index];
    if largest > max && !too_big {
        out.push(
            Diagnostic::warning(
                "W302",
                format!(
                    "the largest configuration of {} needs {largest} {direction} bytes (status bytes included), more than {attribute}={max}",
                    describe(dap)
                ),
            )
            .at(value_span(config, attribute))
            .label(format!("largest configuration: {largest}"))
            .help("the engineering tool refuses configurations beyond the limit; raise it if the device can carry more"),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_slot_counts_its_largest_module() {
        let list = |text| ValueList::parse(text).unwrap();
        let placements = [
            (list("1..3"), Io([4, 1])),
            (list("2..5"), Io([6, 0])),
            (list("2..32767"), Io([1, 0])),
        ];
        // Input: slot 1 takes 4, slots 2..5 take 6, slots 6..32767 take 1.
        assert_eq!(sum_of_slot_maxima(&placements, 0), 4 + 4 * 6 + 32762);
        // Output: only slots 1..3 have any.
        assert_eq!(sum_of_slot_maxima(&placements, 1), 3);
    }
}
