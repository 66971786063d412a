#!/usr/bin/env python3
"""The IO controller side of gsdc's PROFINET wire test.

It knows the device only from the GSDML file: profinet-py (GPL-3.0, run here
as a separate process and never linked into gsdc) reads the module catalogue
and drives DCP, the AR and the cyclic exchange; this program reads the
GSDML's parameter records and the names of its data items itself (profinet-py
has no reader for them). For one module in one slot (with --also, other
modules in other slots at the same time, each its own telegram, whose
records it writes and whose inputs it observes too) it:

1. finds the device by its name of station (DCP Identify) and connects with
   the module the GSDML describes (ExpectedSubmodule block and IOCRs);
2. writes every parameter record of the device access point's own submodule
   and its ports (slot 0), then of the module's submodules, each record
   alone, with values other than the GSDML's defaults where the record may be
   changed, and checks that the device decoded exactly those values through
   its layout (the device's own account, its JSON events file);
3. ends parameterisation (PrmEnd), answers ApplicationReady, exchanges cyclic
   data, and checks what a scenario from the manual asks for: the status word
   answering a control word, the PKW channel answering a request; and each
   32-bit value (standard telegram 2's NSOLL_B) read by the layout as it was
   written;
4. or, with --expect-refusal, checks that the device refuses the Connect and
   says with which PNIO status.

Exit status: 0 every check passed, 1 one failed (the failure is printed with
the module, byte offset and both values where it can tell), 2 the exchange
could not be run (usage, no device, a GSDML this program cannot read).

What profinet-py 0.6.6 does that the device (pnio 0.1.0) does not take, and
what this program changes at run time, from its side only (`_adjust`):
- it proposes input frame IDs 0xC000 + n, and pnio accepts 0x8000..0xBBFF:
  the proposed ID is moved into that range;
- it reads a refusal's PNIO status as little-endian, where pnio (as the
  standard) sends it big-endian: the raw status is kept and printed;
- its write_multiple wraps the records in a second MultipleWrite container:
  this program writes each record alone instead.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import logging

import profinet.exceptions
from profinet import gsdml as pgsdml
from profinet.cyclic import CyclicController
from profinet.rpc import IOCRSetup, RPCCon, get_station_info
from profinet.rt import build_iocr_configs
from profinet.util import ethernet_socket, get_mac

# The cycle: the shortest the GSDML's SendClock and ReductionRatio allow of
# at least 8 ms (256 x 31.25 us), which Python keeps (profinet-py warns
# below 8 ms). The watchdog and the device's data hold time: 30 cycles
# (240 ms at 8 ms): on a machine of two cores shared with compilers, 10
# cycles (80 ms) let a scheduling pause of the Python sender end an AR.
SHORTEST_CYCLE = 256
WATCHDOG_FACTOR = 30
# How long an answer may take: it ends at the answer, and the slowest seen
# with both cores busy was 1.4 s from DCP identify to first data.
ANSWER_SECONDS = 5.0
# The GSDML schema's defaults for TimingProperties.
DEFAULT_SEND_CLOCKS = "32"
DEFAULT_REDUCTION_RATIOS = "1 2 4 8 16 32 64 128 256 512"

TYPE_SIZES = {
    "Unsigned8": 1, "Integer8": 1, "Unsigned16": 2, "Integer16": 2,
    "Unsigned32": 4, "Integer32": 4, "Float32": 4, "N2": 2, "N4": 4,
}

CONNECT_FIELDS = {
    (0x02, 0x0F): "IOCRBlockReq, number of APIs",
    (0x03, 0x04): "ExpectedSubmoduleBlockReq, module ident number",
    (0x03, 0x05): "ExpectedSubmoduleBlockReq, API",
    (0x03, 0x06): "ExpectedSubmoduleBlockReq, submodule ident number",
    (0x03, 0x07): "ExpectedSubmoduleBlockReq, submodule missing or its data length",
}


class Failed(Exception):
    """A check failed: exit 1."""


class CannotRun(Exception):
    """The exchange could not be run: exit 2."""


# ---------------------------------------------------------------- the GSDML

@dataclass
class Ref:
    data_type: str
    byte_offset: int
    default: int
    allowed: list[tuple[int, int]]
    changeable: bool
    name: str
    # A Bit's or BitArea's first bit and bits; 0 bits for whole bytes.
    bit_offset: int = 0
    bit_length: int = 0


@dataclass
class RecordItem:
    index: int
    length: int
    name: str
    refs: list[Ref]


@dataclass
class DataItem:
    name: str
    offset: int
    size: int
    bits: dict[str, int] = field(default_factory=dict)


@dataclass
class Submodule:
    subslot: int
    ident: int
    api: int
    inputs: list[DataItem]
    outputs: list[DataItem]
    records: list[RecordItem]


class Gsdml:
    """What this program reads of a GSDML itself: texts, records, data items."""

    def __init__(self, path: Path):
        self.root = ET.parse(path).getroot()
        self.texts = {}
        primary = self.root.find(".//{*}PrimaryLanguage")
        for text in primary.findall("{*}Text") if primary is not None else []:
            self.texts[text.get("TextId")] = text.get("Value")

    def cycle(self) -> tuple[int, int]:
        """(send clock factor, reduction ratio) of the shortest cycle of at
        least SHORTEST_CYCLE the interface's TimingProperties allow."""
        timing = self.root.find(".//{*}InterfaceSubmoduleItem/{*}ApplicationRelations/{*}TimingProperties")
        get = (lambda name, default: timing.get(name, default)) if timing is not None else (lambda _, d: d)
        clocks = [int(c) for c in get("SendClock", DEFAULT_SEND_CLOCKS).split()]
        ratios = [int(r) for r in get("ReductionRatio", DEFAULT_REDUCTION_RATIOS).split()]
        cycles = [(c * r, c, r) for c in clocks for r in ratios if c * r >= SHORTEST_CYCLE]
        if not cycles:
            raise CannotRun(f"no cycle of at least {SHORTEST_CYCLE / 32:g} ms in SendClock {clocks} x ReductionRatio {ratios}")
        _, clock, ratio = min(cycles)
        return clock, ratio

    def dap(self, number: int) -> ET.Element:
        """The DeviceAccessPointItem `number` (from 1, in the file's order)."""
        daps = self.root.findall(".//{*}DeviceAccessPointItem")
        if not 1 <= number <= len(daps):
            raise CannotRun(f"the GSDML has {len(daps)} DeviceAccessPointItem, not a number {number}")
        return daps[number - 1]

    def module(self, module_id: str) -> ET.Element:
        for item in self.root.iter():
            if item.tag.endswith("}ModuleItem") and item.get("ID") == module_id:
                return item
        raise CannotRun(f"the GSDML has no ModuleItem {module_id!r}")

    def submodules(self, module_id: str) -> list[Submodule]:
        module = self.module(module_id)
        api = 0
        subs = []
        for number, item in enumerate(module.findall(".//{*}VirtualSubmoduleItem"), start=1):
            fixed = item.get("FixedInSubslots")
            subslot = int(fixed.split()[0]) if fixed else number
            api = int(item.get("API", "0"), 0)
            subs.append(Submodule(
                subslot=subslot,
                ident=int(item.get("SubmoduleIdentNumber"), 0),
                api=api,
                inputs=self._data_items(item.find("{*}IOData/{*}Input")),
                outputs=self._data_items(item.find("{*}IOData/{*}Output")),
                records=[self._record(r) for r in item.findall(".//{*}ParameterRecordDataItem")],
            ))
        return subs

    def _data_items(self, direction) -> list[DataItem]:
        items, offset = [], 0
        for item in direction.findall("{*}DataItem") if direction is not None else []:
            size = int(item.get("Length")) if item.get("Length") else TYPE_SIZES[item.get("DataType")]
            bits = {self.texts.get(b.get("TextId"), ""): int(b.get("BitOffset"))
                    for b in item.findall("{*}BitDataItem")}
            items.append(DataItem(self.texts.get(item.get("TextId"), ""), offset, size, bits))
            offset += size
        return items

    def own_submodules(self, dap: ET.Element) -> list[Submodule]:
        """The submodules of slot 0 with parameter records: the DAP's own
        (in its FixedInSubslots, else 1) and its ports."""
        subs = []
        for item in dap.findall("{*}VirtualSubmoduleList/{*}VirtualSubmoduleItem"):
            fixed = item.get("FixedInSubslots")
            subs.append(self._own_submodule(item, int(fixed.split()[0]) if fixed else 1))
        for item in dap.findall("{*}SystemDefinedSubmoduleList/{*}PortSubmoduleItem"):
            subs.append(self._own_submodule(item, int(item.get("SubslotNumber"))))
        return [s for s in subs if s.records]

    def _own_submodule(self, item, subslot: int) -> Submodule:
        return Submodule(
            subslot=subslot,
            ident=int(item.get("SubmoduleIdentNumber"), 0),
            api=0,
            inputs=[],
            outputs=[],
            records=[self._record(r) for r in item.findall(".//{*}ParameterRecordDataItem")],
        )

    def _record(self, item) -> RecordItem:
        name = item.find("{*}Name")
        refs = []
        for ref in item.findall("{*}Ref"):
            data_type = ref.get("DataType")
            bit_length = {"Bit": 1, "BitArea": int(ref.get("BitLength", "1"))}.get(data_type, 0)
            allowed = ref.get("AllowedValues")
            refs.append(Ref(
                data_type=data_type,
                byte_offset=int(ref.get("ByteOffset")),
                default=int(ref.get("DefaultValue", "0"), 0),
                # Without AllowedValues, every value of its type.
                allowed=_ranges(allowed) if allowed else [(0, _type_max(data_type, bit_length))],
                changeable=ref.get("Changeable", "true") == "true",
                name=self.texts.get(ref.get("TextId"), ref.get("TextId")),
                bit_offset=int(ref.get("BitOffset", "0")),
                bit_length=bit_length,
            ))
        return RecordItem(
            index=int(item.get("Index"), 0),
            length=int(item.get("Length")),
            name=self.texts.get(name.get("TextId")) if name is not None else "",
            refs=refs,
        )


def _type_max(data_type: str, bit_length: int) -> int:
    """The most an unsigned value of the type holds."""
    if bit_length:
        return (1 << bit_length) - 1
    if not data_type.startswith("Unsigned"):
        raise CannotRun(f"a record Ref of {data_type} without AllowedValues: this program writes unsigned values only there")
    return (1 << (8 * TYPE_SIZES[data_type])) - 1


def _ranges(text: str | None) -> list[tuple[int, int]]:
    """AllowedValues "0..14 20 30..31" as inclusive ranges."""
    ranges = []
    for part in (text or "").split():
        low, _, high = part.partition("..")
        ranges.append((int(low, 0), int(high or low, 0)))
    return ranges


def other_value(ref: Ref, ordinal: int) -> int:
    """A value the Ref allows other than its default (the default itself
    where the record may not be changed): the (3 x ordinal + 1)-th allowed
    value after the default, counting round the allowed values, so that
    neighbouring entries get different values and a word decoded from the
    wrong offset shows."""
    if not ref.changeable:
        return ref.default
    sizes = [high - low + 1 for low, high in ref.allowed]
    total = sum(sizes)

    def nth(position: int) -> int:
        for (low, _), size in zip(ref.allowed, sizes):
            if position < size:
                return low + position
            position -= size
        raise AssertionError("position within the allowed values")

    start = 0
    for (low, high), size in zip(ref.allowed, sizes):
        if low <= ref.default <= high:
            start += ref.default - low
            break
        start += size
    else:
        start = -1  # the default is not among the allowed values
    value = nth((start + 1 + 3 * ordinal) % total)
    value = value if value != ref.default or total == 1 else nth((start + 2 + 3 * ordinal) % total)
    # A 32-bit value uses its high word too, so that a decoder that reads
    # two bytes of it shows.
    wide = value + 0x10000
    if TYPE_SIZES.get(ref.data_type) == 4 and any(low <= wide <= high for low, high in ref.allowed):
        return wide
    return value


def encode_record(record: RecordItem) -> tuple[bytes, list[int]]:
    """The record's bytes and its values, in the GSDML's order of its Refs
    (the order the layout decodes them in)."""
    data = bytearray(record.length)
    values = []
    for ordinal, ref in enumerate(record.refs):
        value = other_value(ref, ordinal)
        if ref.bit_length:
            data[ref.byte_offset] |= value << ref.bit_offset
        else:
            size = TYPE_SIZES[ref.data_type]
            signed = ref.data_type.startswith("Integer")
            data[ref.byte_offset:ref.byte_offset + size] = value.to_bytes(size, "big", signed=signed)
        values.append(value)
    return bytes(data), values


# ------------------------------------------------- adjustments to profinet-py

RAW_STATUS: list[int] = []


def _adjust() -> None:
    """The run-time changes to profinet-py 0.6.6 the module docstring lists."""
    build_iocr = RPCCon._build_iocr_block

    def build_iocr_in_pnio_range(self, iocr_type, iocr_reference, setup):
        block = bytearray(build_iocr(self, iocr_type, iocr_reference, setup))
        # IOCRBlockReq: 6 bytes of block header, then type, reference, LT (2
        # each), properties (4), data length (2): the frame ID is at 18.
        if iocr_type == 1 and block[18] & 0xF0 == 0xC0:
            block[18] = 0x80 | (block[18] & 0x0F)
        return bytes(block)

    RPCCon._build_iocr_block = build_iocr_in_pnio_range

    from_args_status = profinet.exceptions.PNIOError.from_args_status.__func__

    def keep_raw_status(cls, args_status):
        RAW_STATUS.append(args_status)
        return from_args_status(cls, args_status)

    profinet.exceptions.PNIOError.from_args_status = classmethod(keep_raw_status)


def status_text(status: int) -> str:
    raw = status.to_bytes(4, "big")
    text = " ".join(f"{b:02X}" for b in raw)
    if raw[0] == 0xDB and raw[1] == 0x81:
        text += f" (Connect refused: {CONNECT_FIELDS.get((raw[2], raw[3]), 'block %02X field %02X' % (raw[2], raw[3]))})"
    return text


# ------------------------------------------------------------ the exchange

class DeviceEvents:
    """The device's account of the exchange: its JSON lines."""

    def __init__(self, path: Path):
        self.path = path

    def all(self) -> list[dict]:
        if not self.path.exists():
            return []
        return [json.loads(line) for line in self.path.read_text().splitlines() if line.startswith("{")]

    def wait_for(self, match, seconds: float = ANSWER_SECONDS):
        deadline = time.monotonic() + seconds
        while True:
            found = [e for e in self.all() if match(e)]
            if found or time.monotonic() > deadline:
                return found
            time.sleep(0.02)


def say(text: str) -> None:
    print(text, flush=True)


def io_slots(path: Path, dap_id: str, plugged: list[tuple[int, str, list[Submodule]]]):
    """profinet-py's IO slots for the modules plugged, each (slot, ModuleItem
    ID, its submodules)."""
    device = pgsdml.load_gsdml(path)
    assignment = {slot: module_id for slot, module_id, _ in plugged}
    slots = device.build_io_slots(slot_assignment=assignment, dap_id=dap_id)
    # profinet-py numbers a module's submodules 1, 2, ... in their order;
    # the GSDML's FixedInSubslots is what counts.
    for slot, module_id, subs in plugged:
        mine = [s for s in slots if s.slot == slot]
        if len(mine) != len(subs):
            raise CannotRun(f"profinet-py found {len(mine)} submodules in {module_id}, the GSDML {len(subs)}")
        for io_slot, sub in zip(mine, subs):
            if io_slot.submodule_ident != sub.ident:
                raise CannotRun(f"{module_id}: profinet-py and this program read different submodules")
            io_slot.subslot = sub.subslot
    return slots


def connect(args, slots, cycle: tuple[int, int]):
    t0 = time.monotonic()
    sock = ethernet_socket(args.iface)
    try:
        src = get_mac(args.iface)
        info = get_station_info(sock, src, args.station, timeout_sec=3)
    except profinet.exceptions.ProfinetError as e:
        raise CannotRun(f"DCP: no device {args.station!r} answered on {args.iface}: {e}") from e
    finally:
        sock.close()
    say(f"DCP identify: {info.name} at {info.ip}, vendor 0x{info.vendor_high:02X}{info.vendor_low:02X}"
        f" device 0x{info.device_high:02X}{info.device_low:02X} ({(time.monotonic() - t0) * 1000:.0f} ms)")
    setup = IOCRSetup(slots=slots, send_clock_factor=cycle[0], reduction_ratio=cycle[1],
                      watchdog_factor=WATCHDOG_FACTOR, data_hold_factor=WATCHDOG_FACTOR)
    rpc = RPCCon(info, timeout=3)
    return rpc, info, src, setup, t0


def check_identity(gsdml: Gsdml, info) -> None:
    identity = gsdml.root.find(".//{*}DeviceIdentity")
    want = (int(identity.get("VendorID"), 0), int(identity.get("DeviceID"), 0))
    got = (info.vendor_high << 8 | info.vendor_low, info.device_high << 8 | info.device_low)
    if want != got:
        raise Failed(f"DCP identity: vendor/device 0x{got[0]:04X}/0x{got[1]:04X}, the GSDML says 0x{want[0]:04X}/0x{want[1]:04X}")


def write_records(rpc, events: DeviceEvents, slot: int, subs: list[Submodule]) -> dict[tuple[int, int], list[int]]:
    written = {}
    for sub in subs:
        for record in sub.records:
            data, values = encode_record(record)
            rpc.write(sub.api, slot, sub.subslot, record.index, data)
            written[(sub.subslot, record.index)] = values
            say(f"  record {record.index} ({record.name}) to slot {slot} subslot {sub.subslot}: "
                f"{data.hex(' ')} = {values}")
            seen = events.wait_for(lambda e, s=sub.subslot, i=record.index: e.get("event") == "record"
                                   and e["slot"] == slot and e["subslot"] == s and e["index"] == i)
            check_decoded(record, data, values, seen, slot, sub.subslot)
    return written


def check_decoded(record, data, values, seen, slot, subslot) -> None:
    where = f"record {record.index} of slot {slot} subslot {subslot}"
    if not seen:
        raise Failed(f"{where}: the device reported no such write")
    event = seen[-1]
    if event.get("bytes") != data.hex():
        raise Failed(f"{where}: the device received {event.get('bytes')}, the controller wrote {data.hex()}")
    if event.get("layout") is None:
        raise Failed(f"{where}: the device's layout has no record there")
    if "refused" in event:
        raise Failed(f"{where}: the layout's decoder refused it: {event['refused']}")
    entries = event["layout"][:len(values)]
    decoded = [e["value"] for e in entries]
    for ordinal, (want, got) in enumerate(zip(values, decoded)):
        if want != got:
            ref = record.refs[ordinal]
            raise Failed(f"{where}, byte {ref.byte_offset} ({ref.name}): the layout decoded {got} "
                         f"as {entries[ordinal]['entry']!r}, the controller wrote {want}")
    if len(decoded) < len(values):
        raise Failed(f"{where}: the layout decoded {len(decoded)} entries, the GSDML has {len(values)}")
    if event.get("drive_refused"):
        raise Failed(f"{where}: the drive refused the value of {', '.join(event['drive_refused'])}")
    say(f"    decoded by the layout: " + ", ".join(f"{e['entry']} = {e['value']}" for e in entries))


def item(items: list[DataItem], name: str) -> DataItem | None:
    return next((i for i in items if i.name == name), None)


def exchange(cyclic, slot: int, sub: Submodule, out: bytes, until, seconds: float = ANSWER_SECONDS):
    cyclic.set_output_data(slot, sub.subslot, out)
    deadline = time.monotonic() + seconds
    data = None
    while time.monotonic() < deadline:
        data = cyclic.get_input_data(slot, sub.subslot)
        if data is not None and until(data):
            return data
        time.sleep(0.004)
    return data


def word(data: bytes, offset: int) -> int:
    return int.from_bytes(data[offset:offset + 2], "big")


def run_scenario(cyclic, slot: int, subs: list[Submodule], scenario: dict, written) -> int:
    checks = 0
    for sub in (s for s in subs if s.outputs and s.inputs):
        out = bytearray(sum(i.size for i in sub.outputs))
        control = scenario.get("control")
        command = next((i for i in sub.outputs if control and control["set"] in i.bits), None)
        status = next((i for i in sub.inputs if control and all(b in i.bits for b in control["expect_set"] + control["expect_clear"])), None)
        if command and status:
            out[command.offset:command.offset + 2] = (1 << command.bits[control["set"]]).to_bytes(2, "big")
            want_set = [status.bits[b] for b in control["expect_set"]]
            want_clear = [status.bits[b] for b in control["expect_clear"]]

            def answered(d):
                w = word(d, status.offset)
                return all(w >> b & 1 for b in want_set) and not any(w >> b & 1 for b in want_clear)
            data = exchange(cyclic, slot, sub, bytes(out), answered)
            got = word(data, status.offset) if data else None
            say(f"  control word 0x{word(out, command.offset):04X} ({control['set']}) -> status word "
                + (f"0x{got:04X}" if got is not None else "none"))
            if data is None or not answered(data):
                raise Failed(f"slot {slot} subslot {sub.subslot}, byte {status.offset}: status word "
                             f"{'none' if got is None else '0x%04X' % got}, expected bits {control['expect_set']} set "
                             f"and {control['expect_clear']} clear ({control['source']})")
            checks += 1
        pkw = scenario.get("pkw")
        request_items = [item(sub.outputs, n) for n in pkw["items"]] if pkw else []
        response_items = [item(sub.inputs, n) for n in pkw["items"]] if pkw else []
        if pkw and all(request_items) and all(response_items):
            for it, value in zip(request_items, pkw["request"]):
                out[it.offset:it.offset + 2] = value.to_bytes(2, "big")
            expected = [expected_value(v, written) for v in pkw["response"]]
            data = exchange(cyclic, slot, sub, bytes(out),
                            lambda d: [word(d, i.offset) for i in response_items] == expected)
            got = [word(data, i.offset) for i in response_items] if data else None
            fmt = lambda ws: " ".join(f"{w:04X}" for w in ws) if ws else "none"  # noqa: E731
            say(f"  PKW {fmt(pkw['request'])} -> {fmt(got)} ({pkw['says']})")
            if got != expected:
                bad = next(((i, g, w) for i, g, w in zip(response_items, got or [], expected) if g != w), None)
                detail = (f", byte {bad[0].offset} ({bad[0].name}): 0x{bad[1]:04X}, expected 0x{bad[2]:04X}"
                          if bad else "")
                raise Failed(f"slot {slot} subslot {sub.subslot}: PKW answer {fmt(got)}, expected {fmt(expected)}"
                             f"{detail} ({pkw['source']})")
            checks += 1
    return checks


# A 32-bit value whose words differ (0x0001, 0x86A0): a layout that swapped
# them would read 0x86A00001.
SPEED = 100000


def follow_32_bit_values(cyclic, events: DeviceEvents, slot: int, subs: list[Submodule]) -> int:
    """Each 4-byte output item (standard telegram 2's NSOLL_B, an Unsigned32
    in the GSDML, which PROFINET sends high byte first) with a 4-byte input
    item at the same place (NIST_B): the controller writes SPEED; the device
    must say its layout read SPEED there, and its drive model (whose actual
    speed follows the setpoint at once, the model's own) send it back."""
    followed = 0
    for sub in (s for s in subs if s.outputs and s.inputs):
        for setpoint in (i for i in sub.outputs if i.size == 4):
            actual = next((i for i in sub.inputs if i.size == 4 and i.offset == setpoint.offset), None)
            if actual is None:
                continue
            out = bytearray(sum(i.size for i in sub.outputs))
            out[setpoint.offset:setpoint.offset + 4] = SPEED.to_bytes(4, "big")
            word = setpoint.offset // 2 + 1  # PZD number: gsdc writes no PKW channel before one
            data = exchange(cyclic, slot, sub, bytes(out),
                            lambda d: int.from_bytes(d[actual.offset:actual.offset + 4], "big") == SPEED)
            read = events.wait_for(lambda e: e.get("event") == "double-word" and e["slot"] == slot
                                   and e["subslot"] == sub.subslot and e["value"] == SPEED)
            got = int.from_bytes(data[actual.offset:actual.offset + 4], "big") if data else None
            say(f"  {setpoint.name} 0x{SPEED:08X} at byte {setpoint.offset} -> the layout read "
                + (f"{SPEED} (PZD{read[0]['word']})" if read else "something else")
                + f" -> {actual.name} " + (f"0x{got:08X}" if got is not None else "none"))
            if not read:
                seen = [e["value"] for e in events.all() if e.get("event") == "double-word" and e["slot"] == slot]
                raise Failed(f"slot {slot} subslot {sub.subslot}, byte {setpoint.offset} ({setpoint.name}): "
                             f"the layout read {seen or 'nothing'}, the controller wrote {SPEED}")
            if read[0]["word"] != word:
                raise Failed(f"slot {slot} subslot {sub.subslot}, byte {setpoint.offset} ({setpoint.name}): "
                             f"the layout read it as PZD{read[0]['word']}, the GSDML places it at PZD{word}")
            if got != SPEED:
                raise Failed(f"slot {slot} subslot {sub.subslot}, byte {actual.offset} ({actual.name}): "
                             f"{'none' if got is None else '0x%08X' % got}, expected 0x{SPEED:08X} "
                             "(the drive model's actual speed follows its setpoint)")
            followed += 1
    return followed


def expected_value(value, written) -> int:
    """A value of the scenario: a number, or the value the controller wrote to
    a record (`{"record": 1, "entry": 0, "otherwise": 0}`)."""
    if isinstance(value, int):
        return value
    for (subslot, index), values in written.items():
        if index == value["record"] and value["entry"] < len(values):
            return values[value["entry"]]
    return value["otherwise"]


def observe_inputs(cyclic, slot: int, subs: list[Submodule]) -> int:
    """Data observed: every submodule with inputs delivers them, valid."""
    count = 0
    for sub in (s for s in subs if s.inputs):
        deadline = time.monotonic() + ANSWER_SECONDS
        data = None
        while data is None and time.monotonic() < deadline:
            data = cyclic.get_input_data(slot, sub.subslot)
            time.sleep(0.004)
        if data is None:
            raise Failed(f"slot {slot} subslot {sub.subslot}: no valid input data in {ANSWER_SECONDS:g} s")
        say(f"  inputs of slot {slot} subslot {sub.subslot}: {data.hex(' ')}")
        count += 1
    return count


def identify(args) -> None:
    """DCP Identify by the GSDML's name of station (its DNS_CompatibleName),
    and the identity the device answers with checked against the GSDML: what
    an engineering tool does first with a soft card."""
    gsdml = Gsdml(args.gsdml)
    station = gsdml.dap(1).get("DNS_CompatibleName")
    sock = ethernet_socket(args.iface)
    try:
        info = get_station_info(sock, get_mac(args.iface), station, timeout_sec=3)
    except profinet.exceptions.ProfinetError as e:
        raise Failed(f"DCP: no device {station!r} answered on {args.iface}: {e}") from e
    finally:
        sock.close()
    check_identity(gsdml, info)
    say(f"DCP identify: {info.name} at {info.ip}, vendor 0x{info.vendor_high:02X}{info.vendor_low:02X}"
        f" device 0x{info.device_high:02X}{info.device_low:02X}, as the GSDML says")


def run(args) -> None:
    gsdml = Gsdml(args.gsdml)
    subs = gsdml.submodules(args.module)
    dap = gsdml.dap(args.dap)
    # The other modules plugged at the same time, each in its own slot.
    also = [(slot, module, gsdml.submodules(module)) for slot, module in args.also]
    slots = io_slots(args.gsdml, dap.get("ID"), [(args.slot, args.module, subs)] + also)
    events = DeviceEvents(args.device_events)
    scenario = json.loads(args.scenario.read_text()) if args.scenario else {}
    say(f"device access point {args.dap} ({dap.get('ID')}, ident {dap.get('ModuleIdentNumber')}), "
        f"{args.module} in slot {args.slot}: " + ", ".join(
        f"subslot {s.subslot} ident 0x{s.ident:X} API 0x{s.api:X} in {sum(i.size for i in s.inputs)} "
        f"out {sum(i.size for i in s.outputs)}" for s in subs)
        + "".join(f"; {module} in slot {slot} at the same time" for slot, module, _ in also))
    cycle = gsdml.cycle()
    rpc, info, src, setup, t0 = connect(args, slots, cycle)
    check_identity(gsdml, info)
    try:
        result = rpc.connect(src, iocr_setup=setup)
    except profinet.exceptions.RPCError as e:
        if args.expect_refusal is not None and RAW_STATUS:
            if RAW_STATUS[-1] != args.expect_refusal:
                raise Failed(f"Connect refused with PNIO status {status_text(RAW_STATUS[-1])}, "
                             f"expected {status_text(args.expect_refusal)}")
            say(f"Connect refused as expected: PNIO status {status_text(RAW_STATUS[-1])}")
            return
        raise Failed(f"Connect failed: " + (f"PNIO status {status_text(RAW_STATUS[-1])}" if RAW_STATUS else str(e)))
    if args.expect_refusal is not None:
        rpc.disconnect()
        raise Failed("the device accepted a Connect it should have refused")
    say(f"Connect: AR up, input frame 0x{result.input_frame_id:04X}, output frame 0x{result.output_frame_id:04X}, "
        f"cycle {cycle[0] * cycle[1] / 32:g} ms (send clock {cycle[0]}, reduction ratio {cycle[1]})")
    apis = sorted({s.api for s in subs})
    cyclic = None
    try:
        own = write_records(rpc, events, 0, gsdml.own_submodules(dap))
        written = write_records(rpc, events, args.slot, subs)
        beside = sum(len(write_records(rpc, events, slot, other)) for slot, _, other in also)
        input_cr, output_cr = build_iocr_configs(slots, result.input_frame_id, result.output_frame_id,
                                                 cycle[0], cycle[1], WATCHDOG_FACTOR)
        mac = info.mac if isinstance(info.mac, bytes) else bytes.fromhex(info.mac.replace(":", ""))
        cyclic = CyclicController(args.iface, src, mac, input_cr, output_cr)
        cyclic.start()
        try:
            rpc.prm_end()
        except profinet.exceptions.RPCError as e:
            raise Failed("PrmEnd refused: " + (status_text(RAW_STATUS[-1]) if RAW_STATUS else str(e)))
        rpc.application_ready(timeout=5)
        first = observe_inputs(cyclic, args.slot, subs)
        first += sum(observe_inputs(cyclic, slot, other) for slot, _, other in also)
        say(f"first data {(time.monotonic() - t0) * 1000:.0f} ms after DCP identify")
        checks = run_scenario(cyclic, args.slot, subs, scenario, written)
        followed = follow_32_bit_values(cyclic, events, args.slot, subs)
        if args.scenario and checks == 0 and scenario.get("required", True) and any(s.outputs for s in subs):
            say("  (the scenario has no check that applies to this module)")
        merged = any(e.get("event") == "merged-apis" for e in events.all())
        if any(api != 0 for api in apis):
            say(f"  API 0x{apis[-1]:X}: the device checked it against its layout before pnio saw the Connect"
                f"{' and merged the IOCRs to one API for pnio' if merged else ''}; pnio itself cannot check an API")
        say(f"PASS {case(args)}: {len(written) + beside} records decoded, {first} inputs observed, {checks} scenario checks"
            + (f", {followed} 32-bit values read by the layout" if followed else "")
            + (f", {len(own)} records of the access point and its ports decoded" if own else ""))
    finally:
        if cyclic is not None:
            cyclic.stop()
        rpc.disconnect()


def case(args) -> str:
    """The exchange's name in its PASS and FAIL lines: the module, the
    modules plugged beside it, and the device access point after the first
    it is plugged under."""
    name = args.module + "".join(f" with {module} in slot {slot}" for slot, module in args.also)
    return name if args.dap == 1 else f"{name} under device access point {args.dap}"


def list_modules(path: Path, number: int) -> int:
    """What the wire test plugs: every module DAP `number` may take, with its
    first and last allowed slot, the highest API of its submodules, whether they
    carry data (1) or not (0: an empty module) and its name (the GSDML's, in
    its primary language, which the device finds the module by); the name of
    station (the DAP's DNS_CompatibleName); how many DAPs the GSDML has;
    and the first DAP of DAP `number`'s ModuleIdentNumber (a device presenting
    it cannot tell the two apart). A PROFIsafe module is left out: its data is a safety layer's (an
    F-host's CRC2 over the F-parameters), which neither end here has."""
    gsdml = Gsdml(path)
    dap = gsdml.dap(number)
    daps = gsdml.root.findall(".//{*}DeviceAccessPointItem")
    print(f"daps {len(daps)}")
    ident = int(dap.get("ModuleIdentNumber"), 0)
    same = next(n for n, d in enumerate(daps, 1) if int(d.get("ModuleIdentNumber"), 0) == ident)
    print(f"presented_by {same}")
    print(f"station {dap.get('DNS_CompatibleName')}")
    for ref in dap.findall("{*}UseableModules/{*}ModuleItemRef"):
        slots = ref.get("FixedInSlots") or ref.get("AllowedInSlots")
        first = int(slots.split()[0].split("..")[0])
        last = int(slots.split()[-1].split("..")[-1])
        module = ref.get("ModuleItemTarget")
        if gsdml.module(module).find(".//{*}VirtualSubmoduleItem[@PROFIsafeSupported='true']") is not None:
            continue
        subs = gsdml.submodules(module)
        api = max(s.api for s in subs)
        data = int(any(s.inputs or s.outputs for s in subs))
        name = gsdml.module(module).find("{*}ModuleInfo/{*}Name")
        print(f"module {module} {first} {last} {api} {data} {gsdml.texts.get(name.get('TextId'), '')}")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--gsdml", required=True, type=Path)
    parser.add_argument("--list-modules", action="store_true",
                        help="print each ModuleItem ID with its first and last allowed slot, and the station name")
    parser.add_argument("--identify", action="store_true",
                        help="only DCP Identify the device by the GSDML's name of station, and check its identity")
    parser.add_argument("--iface")
    parser.add_argument("--station")
    parser.add_argument("--module", help="the GSDML's ModuleItem ID")
    parser.add_argument("--slot", type=int, default=1)
    parser.add_argument("--also", action="append", default=[], metavar="SLOT=MODULE",
                        type=lambda v: (int(v.split("=", 1)[0]), v.split("=", 1)[1]),
                        help="another ModuleItem ID plugged in another slot at the same time")
    parser.add_argument("--dap", type=int, default=1,
                        help="the DeviceAccessPointItem to connect with: its number in the GSDML, from 1")
    parser.add_argument("--device-events", type=Path)
    parser.add_argument("--scenario", type=Path)
    parser.add_argument("--expect-refusal", metavar="STATUS", type=lambda h: int(h, 16),
                        help="the PNIO status (hex, e.g. DB810304) the device must refuse the Connect with")
    args = parser.parse_args()
    if args.list_modules:
        return list_modules(args.gsdml, args.dap)
    if args.identify:
        if args.iface is None:
            parser.error("--iface is required")
        try:
            identify(args)
        except Failed as e:
            say(f"FAIL identify: {e}")
            return 1
        return 0
    for needed in ("iface", "station", "module", "device_events"):
        if getattr(args, needed) is None:
            parser.error(f"--{needed.replace('_', '-')} is required")
    # profinet-py warns that its cyclic IO is experimental on every Connect.
    logging.basicConfig(level=logging.ERROR)
    _adjust()
    try:
        run(args)
    except Failed as e:
        say(f"FAIL {case(args)}: {e}")
        return 1
    except CannotRun as e:
        say(f"CANNOT RUN {case(args)}: {e}")
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
