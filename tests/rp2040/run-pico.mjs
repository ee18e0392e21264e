#!/usr/bin/env node
// Runs a MicroTrace Raspberry Pi Pico example image in the rp2040js emulator and captures what it
// sends to its display.
//
//   node run-pico.mjs <ssd1306|st7789> <elf> <bootrom> <out-prefix>
//        [--uf2 FILE] [--max-cycles N] [--idle-cycles N] [--start rom|boot2] [--png-scale N] [--verbose]
//
// With `--uf2 FILE` the flash is written from that UF2 file (the file a user drags onto the
// Pico in BOOTSEL mode: 512-byte blocks, family RP2040, 256-byte payloads) instead of from the
// ELF's loadable segments; the ELF still names functions in messages and decodes the log.
//
// The image boots from the boot ROM's reset vector (default, `--start rom`): the ROM checks the
// chip-reset register and the QSPI chip-select strap, reads boot2 (256 bytes, CRC-checked) from
// a modelled SPI flash behind the SSI, and boot2 enters the image's vector table. `--start boot2`
// skips the ROM's boot path instead (PC = 0x10000000, as rp2040js's own demo does); the ROM is
// still loaded, for its soft-float routines.
//
// Outputs (<out-prefix> + ...):
//   ssd1306: .pages.bin (the 1024 bytes of the SSD1306's GDDRAM: byte [page*128 + column], bit k
//            = row 8*page + k, LSB at the top, 1 = lit), .pbm (P4 128x64, lit = white),
//            .png, .commands.json (the command stream)
//   st7789:  .rgb565 (240x240 pixels, 2 bytes each, big-endian as sent on the bus, rows top to
//            bottom), .ppm (P6, each primary expanded to 8 bits), .png, .commands.json
//   both:    .defmt.bin (raw bytes of the defmt-rtt up channel 0, for `defmt-print -e <elf>`)
// A JSON summary goes to stdout. Exit status 0 when the image drew and went idle; 1 on a fault,
// on --max-cycles, or when nothing was drawn; 2 on a usage error.

import { readFileSync, writeFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { RP2040, BasePeripheral, I2CMode } from 'rp2040js';

const require = createRequire(import.meta.url);
// package.json is not among rp2040js's exports: find it beside its entry point (dist/cjs/index.js)
const RP2040JS_VERSION = JSON.parse(
  readFileSync(join(dirname(require.resolve('rp2040js')), '..', '..', 'package.json'), 'utf8'),
).version;

const CLOCK_HZ = 125_000_000; // rp2040js's simulation clock: one cycle = 8 ns
const NANOS_PER_CYCLE = 1e9 / CLOCK_HZ;
const FLASH_BASE = 0x10000000;
const FLASH_SIZE = 2 * 1024 * 1024; // the Pico's W25Q16JV
const BOOT2_SRAM = 0x20041f00; // the ROM copies boot2 to the last 256 bytes of SRAM

// ---------------------------------------------------------------------------------------------
// Command line

function usage(message) {
  if (message) process.stderr.write(`run-pico: ${message}\n`);
  process.stderr.write(
    'usage: node run-pico.mjs <ssd1306|st7789> <elf> <bootrom> <out-prefix> ' +
      '[--uf2 FILE] [--max-cycles N] [--idle-cycles N] [--start rom|boot2] [--png-scale N] [--verbose]\n',
  );
  process.exit(2);
}

function parseArgs(argv) {
  const positional = [];
  const options = { maxCycles: 3e9, idleCycles: 500e6, start: 'rom', pngScale: 1, verbose: false };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) usage(`${arg} needs a value`);
      return argv[++i];
    };
    const number = () => {
      const n = Number(value());
      if (!Number.isFinite(n) || n <= 0) usage(`${arg} needs a positive number`);
      return n;
    };
    if (arg === '--uf2') options.uf2 = value();
    else if (arg === '--max-cycles') options.maxCycles = number();
    else if (arg === '--idle-cycles') options.idleCycles = number();
    else if (arg === '--png-scale') options.pngScale = Math.floor(number());
    else if (arg === '--start') {
      options.start = value();
      if (!['rom', 'boot2'].includes(options.start)) usage('--start is rom or boot2');
    } else if (arg === '--verbose') options.verbose = true;
    else if (arg.startsWith('--')) usage(`unknown option ${arg}`);
    else positional.push(arg);
  }
  if (positional.length !== 4) usage('expected 4 arguments');
  const [display, elf, bootrom, outPrefix] = positional;
  if (!['ssd1306', 'st7789'].includes(display)) usage(`unknown display ${display}`);
  return { display, elf, bootrom, outPrefix, ...options };
}

const hex = (n, digits = 8) => '0x' + (n >>> 0).toString(16).padStart(digits, '0');
const hex2 = (n) => (n & 0xff).toString(16).padStart(2, '0');

// ---------------------------------------------------------------------------------------------
// UF2 (Microsoft's USB flashing format, as the RP2040's boot ROM takes it): 512-byte blocks,
// each with its target address and up to 476 bytes of payload (256 for the RP2040)

const UF2_MAGIC_START0 = 0x0a324655;
const UF2_MAGIC_START1 = 0x9e5d5157;
const UF2_MAGIC_END = 0x0ab16f30;
const UF2_FLAG_FAMILY_ID = 0x00002000;
const UF2_FAMILY_RP2040 = 0xe48bff56;

// Writes every block's payload into `flashImage`; returns the number of blocks. Throws on a
// block the RP2040's boot ROM would not take.
function loadUf2(bytes, flashImage) {
  if (bytes.length === 0 || bytes.length % 512 !== 0) throw new Error(`${bytes.length} bytes: not a whole number of 512-byte blocks`);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const count = bytes.length / 512;
  for (let block = 0; block < count; block++) {
    const at = block * 512;
    const word = (offset) => view.getUint32(at + offset, true);
    const where = `block ${block}`;
    if (word(0) !== UF2_MAGIC_START0 || word(4) !== UF2_MAGIC_START1 || word(508) !== UF2_MAGIC_END) throw new Error(`${where}: bad magic numbers`);
    if (!(word(8) & UF2_FLAG_FAMILY_ID) || word(28) !== UF2_FAMILY_RP2040) throw new Error(`${where}: not for the RP2040 family (flags ${hex(word(8))}, family ${hex(word(28))})`);
    const [address, size, number, total] = [word(12), word(16), word(20), word(24)];
    if (number !== block || total !== count) throw new Error(`${where}: numbered ${number} of ${total}, expected ${block} of ${count}`);
    if (size !== 256 || address % 256 !== 0) throw new Error(`${where}: ${size} bytes at ${hex(address)}, not 256 at a 256-byte boundary`);
    if (address < FLASH_BASE || address + size > FLASH_BASE + FLASH_SIZE) throw new Error(`${where}: ${hex(address)} is not in the 2 MB flash`);
    flashImage.set(bytes.subarray(at + 32, at + 32 + size), address - FLASH_BASE);
  }
  return count;
}

// ---------------------------------------------------------------------------------------------
// ELF32 (little-endian ARM): PT_LOAD segments by physical address, and the symbol table

function parseElf(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (view.getUint32(0, false) !== 0x7f454c46) throw new Error('not an ELF file');
  if (bytes[4] !== 1 || bytes[5] !== 1) throw new Error('not a little-endian ELF32 file');
  if (view.getUint16(18, true) !== 40) throw new Error('not an ARM ELF file');
  const entry = view.getUint32(24, true);
  const phoff = view.getUint32(28, true);
  const shoff = view.getUint32(32, true);
  const phentsize = view.getUint16(42, true);
  const phnum = view.getUint16(44, true);
  const shentsize = view.getUint16(46, true);
  const shnum = view.getUint16(48, true);
  const shstrndx = view.getUint16(50, true);
  const segments = [];
  for (let i = 0; i < phnum; i++) {
    const p = phoff + i * phentsize;
    segments.push({
      type: view.getUint32(p, true),
      offset: view.getUint32(p + 4, true),
      vaddr: view.getUint32(p + 8, true),
      paddr: view.getUint32(p + 12, true),
      filesz: view.getUint32(p + 16, true),
      memsz: view.getUint32(p + 20, true),
    });
  }
  const sections = [];
  for (let i = 0; i < shnum; i++) {
    const s = shoff + i * shentsize;
    sections.push({
      type: view.getUint32(s + 4, true),
      addr: view.getUint32(s + 12, true),
      offset: view.getUint32(s + 16, true),
      size: view.getUint32(s + 20, true),
      link: view.getUint32(s + 24, true),
      entsize: view.getUint32(s + 36, true),
    });
  }
  const sectionName = (i) => {
    const names = sections[shstrndx];
    if (!names) return '';
    let start = names.offset + view.getUint32(shoff + i * shentsize, true);
    let end = start;
    while (bytes[end] !== 0) end++;
    return Buffer.from(bytes.subarray(start, end)).toString('latin1');
  };
  const defmtSection = sections.findIndex((x, i) => i > 0 && x.type === 1 && x.addr === 0 && x.size > 0 && sectionName(i) === '.defmt');
  const defmt = new Map(); // index -> { tag, data }
  const symbols = new Map(); // name -> { value, size, type }
  const functions = []; // { start, end, name }
  for (const section of sections) {
    if (section.type !== 2 /* SHT_SYMTAB */) continue;
    const strtab = sections[section.link];
    const cstring = (offset) => {
      let end = strtab.offset + offset;
      while (bytes[end] !== 0) end++;
      return Buffer.from(bytes.subarray(strtab.offset + offset, end)).toString('latin1');
    };
    for (let s = section.offset; s + 16 <= section.offset + section.size; s += section.entsize || 16) {
      const name = cstring(view.getUint32(s, true));
      const value = view.getUint32(s + 4, true);
      const size = view.getUint32(s + 8, true);
      const type = bytes[s + 12] & 0xf;
      if (!name) continue;
      if (view.getUint16(s + 14, true) === defmtSection && name.startsWith('{')) {
        try {
          const entry = JSON.parse(name);
          defmt.set(value, { tag: entry.tag, data: entry.data });
        } catch {
          // not a defmt string
        }
        continue;
      }
      symbols.set(name, { value, size, type });
      if (type === 2 /* STT_FUNC */ && size > 0) {
        functions.push({ start: value & ~1, end: (value & ~1) + size, name });
      }
    }
  }
  functions.sort((a, b) => a.start - b.start);
  return { entry, segments, symbols, functions, defmt };
}

// Legacy Rust mangling (_ZN...E) to a readable path, without the hash.
function demangle(name) {
  const match = /^_?_ZN(.*)E$/.exec(name);
  if (!match) return name;
  let rest = match[1];
  const parts = [];
  while (rest.length) {
    const len = /^(\d+)/.exec(rest);
    if (!len) return name;
    const n = Number(len[1]);
    parts.push(rest.slice(len[1].length, len[1].length + n));
    rest = rest.slice(len[1].length + n);
  }
  if (parts.length && /^h[0-9a-f]{16}$/.test(parts[parts.length - 1])) parts.pop();
  return parts
    .join('::')
    .replace(/\$LT\$/g, '<')
    .replace(/\$GT\$/g, '>')
    .replace(/\$u20\$/g, ' ')
    .replace(/\$u7b\$/g, '{')
    .replace(/\$u7d\$/g, '}')
    .replace(/\$RF\$/g, '&')
    .replace(/\$C\$/g, ',')
    .replace(/\.\./g, '::');
}

function symbolAt(elf, address) {
  const pc = address & ~1;
  const list = elf.functions;
  let lo = 0;
  let hi = list.length - 1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (list[mid].start <= pc) lo = mid + 1;
    else hi = mid - 1;
  }
  const f = list[hi];
  if (f && pc < f.end) return `${demangle(f.name)}+${hex(pc - f.start, 1)}`;
  if (pc < 0x4000) return 'boot ROM';
  return null;
}

// defmt over RTT: rzCOBS frames (each ended by 0x00, the stream started by one 0x00), each an
// interned-string index (u16 LE) and its arguments. Enough of the wire format for the examples'
// messages (integers, bool, str, istr, nested Format, Display/Debug); else the raw bytes.
function rzcobsFrames(bytes) {
  const frames = [];
  let current = [];
  for (const b of bytes) {
    if (b === 0) {
      if (current.length) frames.push(current);
      current = [];
    } else current.push(b);
  }
  return frames.map((frame) => {
    const out = [];
    const data = frame.slice().reverse();
    let i = 0;
    while (i < data.length) {
      const x = data[i++];
      if (x === 0xff) {
        for (let k = 0; k < 134 && i < data.length; k++) out.push(data[i++]);
      } else if (x & 0x80) {
        out.push(0);
        for (let k = 0; k < (x & 0x7f) + 7 && i < data.length; k++) out.push(data[i++]);
      } else {
        for (let bit = 6; bit >= 0; bit--) out.push(x & (1 << bit) ? 0 : i < data.length ? data[i++] : 0);
      }
    }
    return out.reverse();
  });
}

function decodeDefmt(bytes, table) {
  const messages = [];
  for (const frame of rzcobsFrames(bytes)) {
    let pos = 0;
    const take = (n) => {
      if (pos + n > frame.length) throw new Error('short frame');
      const slice = frame.slice(pos, pos + n);
      pos += n;
      return slice;
    };
    const uint = (n) => take(n).reduceRight((acc, b) => (acc << 8n) | BigInt(b), 0n);
    const sint = (n) => BigInt.asIntN(n * 8, uint(n));
    const format = (index) => {
      const entry = table.get(index);
      if (!entry) throw new Error(`unknown string index ${index}`);
      return entry.data.replace(/\{(=?)([^}]*)\}/g, (_, eq, type) => {
        type = eq ? type.split(':')[0] : '';
        switch (type) {
          case 'u8': return String(uint(1));
          case 'u16': return String(uint(2));
          case 'u32': case 'usize': return String(uint(4));
          case 'u64': return String(uint(8));
          case 'u128': return String(uint(16));
          case 'i8': return String(sint(1));
          case 'i16': return String(sint(2));
          case 'i32': case 'isize': return String(sint(4));
          case 'i64': return String(sint(8));
          case 'bool': return String(uint(1) !== 0n);
          case 'char': return String.fromCodePoint(Number(uint(4)));
          case 'str': case '[u8]': {
            const n = Number(uint(4));
            return Buffer.from(take(n)).toString('utf8');
          }
          case 'istr': return table.get(Number(uint(2)))?.data ?? '?';
          case '__internal_Display': case '__internal_Debug': {
            const end = frame.indexOf(0xff, pos);
            const text = Buffer.from(frame.slice(pos, end < 0 ? frame.length : end)).toString('utf8');
            pos = end < 0 ? frame.length : end + 1;
            return text;
          }
          case '': return format(Number(uint(2))); // a nested Format: its own string and arguments
          default: throw new Error(`unsupported {=${type}}`);
        }
      });
    };
    try {
      const index = Number(uint(2));
      const entry = table.get(index);
      const level = entry?.tag?.replace('defmt_', '') ?? '?';
      messages.push(`${level}: ${format(index)}`);
    } catch (e) {
      messages.push(`(undecoded ${Buffer.from(frame).toString('hex')}: ${e.message})`);
    }
  }
  return messages;
}

// ---------------------------------------------------------------------------------------------
// Stand-ins for what rp2040js does not model, so that the boot ROM's flash boot runs

// A register file: reads return the last value written (or a default); atomic aliases work
// through BasePeripheral.writeUint32Atomic.
class RegisterFile extends BasePeripheral {
  constructor(rp2040, name, defaults = {}, onWrite = null) {
    super(rp2040, name);
    this.values = new Map(Object.entries(defaults).map(([k, v]) => [Number(k), v >>> 0]));
    this.onWrite = onWrite;
  }
  readUint32(offset) {
    return this.values.get(offset) ?? 0;
  }
  writeUint32(offset, value) {
    this.values.set(offset, value >>> 0);
    if (this.onWrite) this.onWrite(offset, value >>> 0);
  }
}

// A W25Q16JV-like serial flash, as the boot ROM and boot2 talk to it through the SSI in standard
// SPI mode. (XIP reads do not come here: rp2040js reads the flash array directly.)
class SerialFlash {
  constructor(data) {
    this.data = data;
    this.selected = false;
    this.index = 0;
    this.command = -1;
    this.address = 0;
    this.commands = {}; // command byte (hex) -> transactions
  }
  select(selected) {
    if (selected === this.selected) return;
    this.selected = selected;
    this.index = 0;
    this.command = -1;
  }
  transfer(byte) {
    if (!this.selected) return 0xff; // nobody drives MISO
    const index = this.index++;
    if (index === 0) {
      this.command = byte;
      const key = hex2(byte);
      this.commands[key] = (this.commands[key] ?? 0) + 1;
      return 0xff;
    }
    switch (this.command) {
      case 0x03: // read data: 3 address bytes, then data
      case 0x0b: // fast read: 3 address bytes, a dummy byte, then data
        if (index <= 3) {
          this.address = ((this.address << 8) | byte) & 0xffffff;
          return 0xff;
        }
        if (this.command === 0x0b && index === 4) return 0xff;
        return this.data[this.address++ % this.data.length];
      case 0x05: // read status register 1: not busy, not write-enabled
        return 0x00;
      case 0x35: // read status register 2: QE set (so boot2 leaves the status registers alone)
        return 0x02;
      case 0x15: // read status register 3
        return 0x00;
      case 0x9f: // JEDEC ID: Winbond W25Q16JV
        return [0xef, 0x40, 0x15][(index - 1) % 3];
      case 0xab: // release power-down / device ID
        return index <= 3 ? 0xff : 0x14;
      case 0x4b: // unique ID: 4 dummy bytes, then 8 bytes
        return index <= 4 ? 0xff : 0xa5;
      default: // 0x00 / 0xff (exit-XIP sequences), 0x06 write enable, ...: no answer
        return 0xff;
    }
  }
}

// The SSI (XIP_SSI_BASE 0x18000000) in standard SPI mode with its TX/RX FIFOs, in front of
// SerialFlash. Transfers complete instantly, so the TX FIFO is always empty and never busy.
// Chip select: forced by IO_QSPI GPIO_QSPI_SS_CTRL.OUTOVER (low / high) as the ROM does; under
// OUTOVER normal (boot2), the SSI selects the flash from the first DR0 write until software has
// drained the RX FIFO (or disables the SSI).
class FlashSSI extends BasePeripheral {
  constructor(rp2040, flash) {
    super(rp2040, 'SSI');
    this.flash = flash;
    this.regs = new Map([[0x00, 0x00070000]]);
    this.enabled = 0;
    this.rx = [];
    this.outover = 0; // 0 normal, 1 invert, 2 low, 3 high
    this.autoSelected = false;
    this.quadFrames = 0;
    this.overruns = 0;
  }
  setOutover(outover) {
    this.outover = outover;
    this.autoSelected = false;
    this.flash.select(outover === 2);
  }
  get frameFormat() {
    return ((this.regs.get(0x00) ?? 0) >> 21) & 3; // CTRLR0.SPI_FRF: 0 standard, 1 dual, 2 quad
  }
  readUint32(offset) {
    if (offset >= 0x60 && offset <= 0xec) {
      // DR0..DR35
      const value = this.rx.length ? this.rx.shift() : 0;
      if (this.outover === 0 && this.autoSelected && this.rx.length === 0) {
        this.autoSelected = false;
        this.flash.select(false);
      }
      return value;
    }
    switch (offset) {
      case 0x08:
        return this.enabled;
      case 0x20: // TXFLR
        return 0;
      case 0x24: // RXFLR
        return this.rx.length;
      case 0x28: // SR: TFNF | TFE | RFNE | RFF, never BUSY
        return 0x2 | 0x4 | (this.rx.length ? 0x8 : 0) | (this.rx.length >= 16 ? 0x10 : 0);
      case 0x30: // ISR
      case 0x34: // RISR
      case 0x38: // TXOICR
      case 0x3c: // RXOICR
      case 0x40: // RXUICR
      case 0x44: // MSTICR
      case 0x48: // ICR
        return 0;
      case 0x58: // IDR
        return 0x51535049;
      case 0x5c: // SSI_VERSION_ID
        return 0x3430312a;
    }
    return this.regs.get(offset) ?? 0;
  }
  writeUint32(offset, value) {
    if (offset >= 0x60 && offset <= 0xec) {
      if (!this.enabled) return;
      if (this.frameFormat !== 0) {
        // boot2's dummy quad read to put the flash in continuous-read mode: nothing to model,
        // and boot2 disables the SSI (clearing the FIFOs) without reading the result.
        this.quadFrames++;
        return;
      }
      if (this.outover === 0 && !this.autoSelected) {
        this.autoSelected = true;
        this.flash.select(true);
      }
      const selected = this.outover === 2 || (this.outover === 0 && this.autoSelected);
      const answer = selected ? this.flash.transfer(value & 0xff) : 0xff;
      if (this.rx.length < 16) this.rx.push(answer);
      else this.overruns++;
      return;
    }
    switch (offset) {
      case 0x08: // SSIENR: disabling clears the FIFOs
        this.enabled = value & 1;
        if (!this.enabled) {
          this.rx = [];
          if (this.outover === 0 && this.autoSelected) {
            this.autoSelected = false;
            this.flash.select(false);
          }
        }
        return;
      default:
        this.regs.set(offset, value >>> 0);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Displays

// SSD1306 128x64 over I2C: control byte (Co bit 7, D/C# bit 6), then commands or GDDRAM data.
const SSD1306_PARAMS = {
  0x20: 1, 0x21: 2, 0x22: 2, 0x26: 6, 0x27: 6, 0x29: 5, 0x2a: 5, 0x81: 1, 0x8d: 1, 0xa3: 2,
  0xa8: 1, 0xad: 1, 0xd3: 1, 0xd5: 1, 0xd6: 1, 0xd9: 1, 0xda: 1, 0xdb: 1,
};
const SSD1306_NAMES = {
  0x20: 'addressing mode', 0x21: 'column address', 0x22: 'page address', 0x2e: 'scroll off',
  0x2f: 'scroll on', 0x81: 'contrast', 0x8d: 'charge pump', 0xa0: 'segment remap off',
  0xa1: 'segment remap on', 0xa4: 'display follows RAM', 0xa5: 'entire display on',
  0xa6: 'normal (not inverted)', 0xa7: 'inverted', 0xa8: 'multiplex ratio', 0xae: 'display off',
  0xaf: 'display on', 0xc0: 'COM scan normal', 0xc8: 'COM scan remapped', 0xd3: 'display offset',
  0xd5: 'clock divide', 0xd9: 'pre-charge period', 0xda: 'COM pins', 0xdb: 'VCOMH deselect',
  0xe3: 'nop',
};

class SSD1306 {
  constructor() {
    this.ram = new Uint8Array(128 * 8);
    this.pagesTouched = new Set();
    this.addressingMode = 2; // reset: page addressing
    this.colStart = 0;
    this.colEnd = 127;
    this.pageStart = 0;
    this.pageEnd = 7;
    this.col = 0;
    this.page = 0;
    this.pending = null; // command being assembled
    this.expectControl = true;
    this.dataMode = false;
    this.single = false;
    this.state = { displayOn: false, contrast: 0x7f, inverted: false, segmentRemap: false, comRemapped: false, startLine: 0, displayOffset: 0, multiplex: 63, chargePump: null, comPins: 0x12, entireOn: false };
    this.commandLog = []; // [{ bytes, name, beforeData }]
    this.commandCounts = {};
    this.unknownCommands = 0;
    this.dataBytes = 0;
    this.controlBytes = 0;
    this.transactions = 0;
    this.flushes = []; // { columns, pages, bytes } per data burst after a window
  }
  startTransaction() {
    this.transactions++;
    this.expectControl = true;
  }
  byte(b) {
    if (this.expectControl) {
      this.controlBytes++;
      this.single = !!(b & 0x80);
      this.dataMode = !!(b & 0x40);
      this.expectControl = false;
      return;
    }
    if (this.dataMode) this.data(b);
    else this.command(b);
    if (this.single) this.expectControl = true;
  }
  command(b) {
    if (this.pending) {
      this.pending.push(b);
    } else {
      this.pending = [b];
    }
    const op = this.pending[0];
    if (this.pending.length - 1 < (SSD1306_PARAMS[op] ?? 0)) return;
    const bytes = this.pending;
    this.pending = null;
    this.apply(bytes);
  }
  apply(bytes) {
    const [op, p1, p2] = bytes;
    let name = SSD1306_NAMES[op];
    const s = this.state;
    if (op === 0x20) this.addressingMode = p1 & 3;
    else if (op === 0x21) {
      this.colStart = p1 & 0x7f;
      this.colEnd = p2 & 0x7f;
      this.col = this.colStart;
      this.flushes.push({ columns: [this.colStart, this.colEnd], pages: null, bytes: 0 });
    } else if (op === 0x22) {
      this.pageStart = p1 & 7;
      this.pageEnd = p2 & 7;
      this.page = this.pageStart;
      const last = this.flushes[this.flushes.length - 1];
      if (last && last.pages === null && last.bytes === 0) last.pages = [this.pageStart, this.pageEnd];
      else this.flushes.push({ columns: null, pages: [this.pageStart, this.pageEnd], bytes: 0 });
    } else if (op === 0x81) s.contrast = p1;
    else if (op === 0x8d) s.chargePump = p1;
    else if (op === 0xa0 || op === 0xa1) s.segmentRemap = op === 0xa1;
    else if (op === 0xa4 || op === 0xa5) s.entireOn = op === 0xa5;
    else if (op === 0xa6 || op === 0xa7) s.inverted = op === 0xa7;
    else if (op === 0xa8) s.multiplex = p1 & 0x3f;
    else if (op === 0xae || op === 0xaf) s.displayOn = op === 0xaf;
    else if (op === 0xc0 || op === 0xc8) s.comRemapped = op === 0xc8;
    else if (op === 0xd3) s.displayOffset = p1 & 0x3f;
    else if (op === 0xda) s.comPins = p1;
    else if (op >= 0x40 && op <= 0x7f) {
      s.startLine = op & 0x3f;
      name = 'display start line';
    } else if (op >= 0xb0 && op <= 0xb7) {
      this.page = op & 7;
      name = 'page start (page mode)';
    } else if (op <= 0x0f) {
      this.col = (this.col & 0xf0) | op;
      name = 'lower column start (page mode)';
    } else if (op >= 0x10 && op <= 0x1f) {
      this.col = ((op & 0x7) << 4) | (this.col & 0x0f);
      name = 'higher column start (page mode)';
    } else if (!name) {
      this.unknownCommands++;
      name = 'unknown (ignored)';
    }
    const key = hex2(op);
    this.commandCounts[key] = (this.commandCounts[key] ?? 0) + 1;
    if (this.commandLog.length < 400) {
      this.commandLog.push({ bytes: bytes.map(hex2).join(' '), name, afterDataBytes: this.dataBytes });
    }
  }
  data(b) {
    this.dataBytes++;
    const last = this.flushes[this.flushes.length - 1];
    if (last) last.bytes++;
    this.ram[this.page * 128 + this.col] = b;
    this.pagesTouched.add(this.page);
    if (this.addressingMode === 0) {
      // horizontal: column first, then page, both within their windows
      if (this.col >= this.colEnd) {
        this.col = this.colStart;
        this.page = this.page >= this.pageEnd ? this.pageStart : this.page + 1;
      } else this.col++;
    } else if (this.addressingMode === 1) {
      // vertical: page first, then column
      if (this.page >= this.pageEnd) {
        this.page = this.pageStart;
        this.col = this.col >= this.colEnd ? this.colStart : this.col + 1;
      } else this.page++;
    } else {
      // page addressing: the column wraps within the page
      this.col = this.col >= 127 ? 0 : this.col + 1;
    }
  }
  lit(x, y) {
    return (this.ram[(y >> 3) * 128 + x] >> (y & 7)) & 1;
  }
}

// ST7789 (240x320 frame memory, a 240x240 panel showing rows 0..239) over SPI with a D/C pin.
const ST7789_NAMES = {
  0x01: 'SWRESET', 0x10: 'SLPIN', 0x11: 'SLPOUT', 0x12: 'PTLON', 0x13: 'NORON', 0x20: 'INVOFF',
  0x21: 'INVON', 0x28: 'DISPOFF', 0x29: 'DISPON', 0x2a: 'CASET', 0x2b: 'RASET', 0x2c: 'RAMWR',
  0x30: 'PTLAR', 0x33: 'VSCRDEF', 0x34: 'TEOFF', 0x35: 'TEON', 0x36: 'MADCTL', 0x37: 'VSCSAD',
  0x38: 'IDMOFF', 0x39: 'IDMON', 0x3a: 'COLMOD', 0x3c: 'RAMWRC', 0x51: 'WRDISBV', 0x53: 'WRCTRLD',
};

class ST7789 {
  constructor() {
    this.memory = new Uint16Array(240 * 320);
    this.written = new Uint8Array(240 * 320); // how many RAMWR pixels landed on each cell (capped)
    this.commandLog = [];
    this.commandCounts = {};
    this.unknownCommands = 0;
    this.bytes = 0;
    this.pixels = 0;
    this.pixelsOutside = 0;
    this.hardwareResets = 0;
    this.windows = new Map(); // "xs-xe,ys-ye" -> count of RAMWR in that window
    this.reset();
  }
  reset() {
    this.madctl = 0;
    this.colmod = 0x66;
    this.inverted = false;
    this.sleeping = true;
    this.displayOn = false;
    this.xs = 0;
    this.xe = 239;
    this.ys = 0;
    this.ye = 319;
    this.command = -1;
    this.params = [];
    this.logEntry = null;
  }
  byte(b, isData) {
    this.bytes++;
    if (!isData) {
      this.command = b;
      this.params = [];
      const key = hex2(b);
      this.commandCounts[key] = (this.commandCounts[key] ?? 0) + 1;
      const name = ST7789_NAMES[b];
      if (!name) this.unknownCommands++;
      this.logEntry = null;
      if (this.commandLog.length < 400) {
        this.logEntry = { command: hex2(b), name: name ?? 'unknown (ignored)', params: '' };
        this.commandLog.push(this.logEntry);
      }
      this.startCommand(b);
      return;
    }
    if (this.command === 0x2c || this.command === 0x3c) {
      this.params.push(b);
      if (this.params.length === 2) {
        this.pixel((this.params[0] << 8) | this.params[1]);
        this.params = [];
        if (this.logEntry) this.logEntry.pixels = (this.logEntry.pixels ?? 0) + 1;
      }
      return;
    }
    this.params.push(b);
    if (this.logEntry && this.params.length <= 16) this.logEntry.params = this.params.map(hex2).join(' ');
    const p = this.params;
    switch (this.command) {
      case 0x2a:
        if (p.length === 4) {
          this.xs = (p[0] << 8) | p[1];
          this.xe = (p[2] << 8) | p[3];
        }
        break;
      case 0x2b:
        if (p.length === 4) {
          this.ys = (p[0] << 8) | p[1];
          this.ye = (p[2] << 8) | p[3];
        }
        break;
      case 0x36:
        if (p.length === 1) this.madctl = b;
        break;
      case 0x3a:
        if (p.length === 1) this.colmod = b;
        break;
    }
  }
  startCommand(b) {
    switch (b) {
      case 0x01:
        this.reset();
        break;
      case 0x10:
        this.sleeping = true;
        break;
      case 0x11:
        this.sleeping = false;
        break;
      case 0x20:
      case 0x21:
        this.inverted = b === 0x21;
        break;
      case 0x28:
      case 0x29:
        this.displayOn = b === 0x29;
        break;
      case 0x2c: {
        this.x = this.xs;
        this.y = this.ys;
        const key = `x ${this.xs}-${this.xe}, y ${this.ys}-${this.ye}`;
        this.windows.set(key, (this.windows.get(key) ?? 0) + 1);
        break;
      }
    }
  }
  pixel(value) {
    this.pixels++;
    // MADCTL: MY (bit 7) mirrors rows, MX (bit 6) mirrors columns, MV (bit 5) swaps them.
    let col = this.x;
    let row = this.y;
    if (this.madctl & 0x20) [col, row] = [row, col];
    if (this.madctl & 0x40) col = 239 - col;
    if (this.madctl & 0x80) row = 319 - row;
    if (col >= 0 && col < 240 && row >= 0 && row < 320) {
      const i = row * 240 + col;
      this.memory[i] = value;
      if (this.written[i] < 255) this.written[i]++;
    } else this.pixelsOutside++;
    if (this.x >= this.xe) {
      this.x = this.xs;
      this.y = this.y >= this.ye ? this.ys : this.y + 1;
    } else this.x++;
  }
}

// ---------------------------------------------------------------------------------------------
// Image files

const CRC_TABLE = (() => {
  const table = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    table[n] = c >>> 0;
  }
  return table;
})();

function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = CRC_TABLE[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

// The boot ROM's check of boot2 (crc32_small): CRC-32/MPEG-2, polynomial 0x04c11db7 MSB first,
// initial value 0xffffffff, no final XOR; compared with boot2's last word.
function crc32Mpeg2(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) {
    c ^= b << 24;
    for (let k = 0; k < 8; k++) c = c & 0x80000000 ? (c << 1) ^ 0x04c11db7 : c << 1;
  }
  return c >>> 0;
}

// PNG, 8-bit grey (channels 1) or RGB (channels 3), each pixel repeated scale x scale.
function png(width, height, channels, pixelAt, scale = 1) {
  const w = width * scale;
  const h = height * scale;
  const raw = Buffer.alloc((w * channels + 1) * h);
  for (let y = 0; y < h; y++) {
    const row = y * (w * channels + 1);
    raw[row] = 0;
    for (let x = 0; x < w; x++) {
      const v = pixelAt(Math.floor(x / scale), Math.floor(y / scale));
      for (let c = 0; c < channels; c++) raw[row + 1 + x * channels + c] = channels === 1 ? v : v[c];
    }
  }
  const chunk = (type, data) => {
    const length = Buffer.alloc(4);
    length.writeUInt32BE(data.length);
    const body = Buffer.concat([Buffer.from(type, 'latin1'), data]);
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(body));
    return Buffer.concat([length, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(w, 0);
  header.writeUInt32BE(h, 4);
  header[8] = 8;
  header[9] = channels === 1 ? 0 : 2;
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('IDAT', deflateSync(raw)),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}

const expand5 = (v) => Math.round((v * 255) / 31);
const expand6 = (v) => Math.round((v * 255) / 63);
const rgb565To888 = (v) => [expand5(v >> 11), expand6((v >> 5) & 0x3f), expand5(v & 0x1f)];

// ---------------------------------------------------------------------------------------------
// Main

function main() {
  const args = parseArgs(process.argv.slice(2));
  const wallStart = performance.now();

  let elfBytes;
  let romBytes;
  try {
    elfBytes = new Uint8Array(readFileSync(args.elf));
  } catch (e) {
    fail(`cannot read the ELF ${args.elf}: ${e.message}`);
  }
  try {
    romBytes = new Uint8Array(readFileSync(args.bootrom));
  } catch (e) {
    fail(
      `cannot read the boot ROM ${args.bootrom}: ${e.message} (the RP2040 B1 mask ROM, 16,384 bytes, ` +
        'from Raspberry Pi\'s pico-bootrom, as rp2040js\'s demo/bootrom.ts ships it)',
    );
  }
  if (romBytes.length !== 16384) fail(`the boot ROM ${args.bootrom} has ${romBytes.length} bytes, not 16,384`);

  const elf = parseElf(elfBytes);
  const flashImage = new Uint8Array(FLASH_SIZE).fill(0xff);
  const loaded = [];
  if (args.uf2) {
    let uf2Bytes;
    try {
      uf2Bytes = new Uint8Array(readFileSync(args.uf2));
    } catch (e) {
      fail(`cannot read the UF2 file ${args.uf2}: ${e.message}`);
    }
    try {
      loaded.push({ uf2: args.uf2, blocks: loadUf2(uf2Bytes, flashImage) });
    } catch (e) {
      fail(`the UF2 file ${args.uf2}: ${e.message}`);
    }
  }
  for (const seg of args.uf2 ? [] : elf.segments) {
    if (seg.type !== 1 /* PT_LOAD */ || seg.filesz === 0) continue;
    if (seg.paddr < FLASH_BASE || seg.paddr + seg.filesz > FLASH_BASE + FLASH_SIZE) {
      fail(`PT_LOAD segment at physical ${hex(seg.paddr)} (${seg.filesz} bytes) is not in the 2 MB flash`);
    }
    flashImage.set(elfBytes.subarray(seg.offset, seg.offset + seg.filesz), seg.paddr - FLASH_BASE);
    loaded.push({ paddr: hex(seg.paddr), vaddr: hex(seg.vaddr), bytes: seg.filesz });
  }
  const boot2Crc = crc32Mpeg2(flashImage.subarray(0, 252));
  const boot2CrcStored = new DataView(flashImage.buffer).getUint32(252, true);
  const vectorTable = 0x100;
  const flashView = new DataView(flashImage.buffer);
  const resetVector = flashView.getUint32(vectorTable + 4, true) & ~1;
  const hardFaultVector = flashView.getUint32(vectorTable + 12, true) & ~1;
  const nmiVector = flashView.getUint32(vectorTable + 8, true) & ~1;
  // The example's own out-of-line `render` (`microtrace_pico_*::render`): the cycle the core
  // first enters it splits the frame into set-up (boot, clocks, display, parsing and preparing
  // the scene) and the render with its display traffic.
  const renderFunction = elf.functions.find((f) => /^microtrace_pico\w*::render$/.test(demangle(f.name).replace(/::h[0-9a-f]{16}$/, '')));
  const renderEntry = renderFunction ? renderFunction.start : -1;

  // The emulated chip
  const rp = new RP2040();
  const warnings = [];
  const warningCounts = {};
  const note = (level) => (component, message) => {
    const key = `${level} [${component}] ${message.replace(/0x[0-9a-f]+|\b[0-9a-f]{5,}\b/gi, '#')}`;
    warningCounts[key] = (warningCounts[key] ?? 0) + 1;
    if (warnings.length < 50) warnings.push(`${level} [${component}] ${message}`);
    if (args.verbose) process.stderr.write(`${level} [${component}] ${message}\n`);
  };
  rp.logger = { debug: () => {}, info: () => {}, warn: note('warn'), error: note('error') };

  rp.loadBootrom(new Uint32Array(romBytes.buffer, romBytes.byteOffset, 4096)); // also resets: flash := 0xff
  rp.flash.set(flashImage, 0);

  const serialFlash = new SerialFlash(flashImage);
  const ssi = new FlashSSI(rp, serialFlash);
  rp.peripherals[0x18000] = ssi; // XIP_SSI_BASE 0x18000000
  // IO_QSPI (0x40018000): GPIO_QSPI_SS_CTRL (0x0c) OUTOVER (bits 9:8) is the flash chip select
  rp.peripherals[0x40018] = new RegisterFile(rp, 'IO_QSPI', {}, (offset, value) => {
    if (offset === 0x0c) ssi.setOutover((value >> 8) & 3);
  });
  // VREG_AND_CHIP_RESET (0x40064000): VREG, BOD at their reset values; CHIP_RESET (0x08) reads
  // HAD_POR (bit 8) only, so PSM_RESTART_FLAG (bit 24) is clear and the ROM does not halt.
  rp.peripherals[0x40064] = new RegisterFile(rp, 'VREG_AND_CHIP_RESET', { 0x00: 0xb1, 0x04: 0x91, 0x08: 0x100 });
  // XIP_CTRL (0x14000000): CTRL (EN), FLUSH, STAT (FIFO_EMPTY | FLUSH_READY)
  rp.peripherals[0x14000] = new RegisterFile(rp, 'XIP_CTRL', { 0x00: 0x3, 0x08: 0x3 });
  // QSPI_SS reads high: the pull-up, BOOTSEL not pressed (rp2040js's pads reset with IE clear).
  rp.qspi[1].padValue |= 0x40;
  rp.qspi[1].setInputValue(true);

  if (args.start === 'boot2') {
    rp.core.PC = FLASH_BASE; // boot2 from flash, as rp2040js's demo does; SP = the ROM's initial SP
  }

  // The display on its bus
  let lastDisplayCycle = -1;
  let firstDisplayCycle = -1;
  let cycles = 0;
  // Instructions executed, beside the cycles: the figure QEMU's plugin counts for the firmware,
  // so the two emulators' counts compare (docs: firmware/README.md, "The Cortex-M0").
  let instructions = 0;
  let lastDisplayInstruction = -1;
  let renderEnteredInstruction = -1;
  const displayByte = () => {
    if (firstDisplayCycle < 0) firstDisplayCycle = cycles;
    lastDisplayCycle = cycles;
    lastDisplayInstruction = instructions;
  };
  let oled = null;
  let panel = null;
  const bus = { nacks: 0, reads: 0, otherAddresses: {}, ignoredBytes: 0, pinFunctions: null };
  if (args.display === 'ssd1306') {
    oled = new SSD1306();
    const i2c = rp.i2c[0];
    let connected = false;
    i2c.onStart = () => i2c.completeStart();
    i2c.onConnect = (address, mode) => {
      if (!bus.pinFunctions) {
        bus.pinFunctions = { GP4: rp.gpio[4].functionSelect, GP5: rp.gpio[5].functionSelect, expected: 3 };
      }
      if (address === 0x3c && mode === I2CMode.Write) {
        connected = true;
        oled.startTransaction();
        i2c.completeConnect(true);
      } else {
        connected = false;
        const key = `${hex2(address)} ${mode === I2CMode.Write ? 'write' : 'read'}`;
        bus.otherAddresses[key] = (bus.otherAddresses[key] ?? 0) + 1;
        bus.nacks++;
        i2c.completeConnect(false);
      }
    };
    i2c.onWriteByte = (value) => {
      if (connected) {
        oled.byte(value);
        displayByte();
      }
      i2c.completeWrite(connected);
    };
    i2c.onReadByte = () => {
      bus.reads++;
      i2c.completeRead(0xff);
    };
    i2c.onStop = () => {
      connected = false;
      i2c.completeStop();
    };
    const other = rp.i2c[1];
    other.onConnect = (address) => {
      bus.otherAddresses[`I2C1 ${hex2(address)}`] = (bus.otherAddresses[`I2C1 ${hex2(address)}`] ?? 0) + 1;
      other.completeConnect(false);
    };
  } else {
    panel = new ST7789();
    const spi = rp.spi[0];
    const dc = rp.gpio[16];
    const cs = rp.gpio[17];
    const rst = rp.gpio[20];
    spi.onTransmit = (value) => {
      if (!bus.pinFunctions) {
        bus.pinFunctions = {
          GP18_SCK: rp.gpio[18].functionSelect,
          GP19_TX: rp.gpio[19].functionSelect,
          expected_spi: 1,
          GP16_DC: rp.gpio[16].functionSelect,
          GP17_CS: rp.gpio[17].functionSelect,
          GP20_RST: rp.gpio[20].functionSelect,
          expected_sio: 5,
          // SSPCR0 SPO (bit 6) = CPOL, SPH (bit 7) = CPHA (rp2040js's spiMode getter swaps modes 2 and 3)
          spi_mode: ((spi.control0 >> 6) & 1) * 2 + ((spi.control0 >> 7) & 1),
          data_bits: spi.dataBits,
          clock_hz: spi.clockFrequency,
        };
      }
      // CS low and RST high select the panel; D/C low = command, high = data
      if (!cs.outputValue && rst.outputValue) {
        panel.byte(value & 0xff, dc.outputValue);
        displayByte();
      } else bus.ignoredBytes++;
      spi.completeTransmit(0);
    };
    // RST low holds the controller in reset; count the pulses that end (low -> high)
    let rstLow = !rst.outputValue;
    rst.addListener(() => {
      const low = !rst.outputValue;
      if (low && !rstLow) panel.reset();
      if (!low && rstLow) panel.hardwareResets++;
      rstLow = low;
    });
    rp.spi[1].onTransmit = () => rp.spi[1].completeTransmit(0);
  }

  // Faults: rp2040js does not raise HardFault, but an image may branch to its handler; BKPT and
  // UDF (panic-probe's end, or a trap) call onBreak.
  let stopReason = null;
  let failure = null;
  rp.onBreak = (code) => {
    const pc = (rp.core.PC - rp.core.breakRewind) >>> 0;
    const where = symbolAt(elf, pc);
    failure = `breakpoint/UDF #${code} at ${hex(pc)}${where ? ` (${where})` : ''}: the image trapped (a panic ends in UDF)`;
    stopReason = 'trap';
  };

  // defmt-rtt's up channel 0, read like a probe would (so that it never fills up)
  const rtt = elf.symbols.get('_SEGGER_RTT');
  const defmtChunks = [];
  let defmtBytes = 0;
  const pollRtt = () => {
    if (!rtt) return;
    const base = rtt.value - 0x20000000;
    const sram = rp.sramView;
    if (base < 0 || base + 48 > rp.sram.length) return;
    const buffer = sram.getUint32(base + 28, true) - 0x20000000;
    const size = sram.getUint32(base + 32, true);
    const write = sram.getUint32(base + 36, true);
    let read = sram.getUint32(base + 40, true);
    if (buffer < 0 || size === 0 || buffer + size > rp.sram.length || write >= size || read >= size) return;
    while (read !== write) {
      const end = write > read ? write : size;
      const chunk = rp.sram.slice(buffer + read, buffer + end);
      defmtChunks.push(chunk);
      defmtBytes += chunk.length;
      read = end === size ? 0 : end;
    }
    sram.setUint32(base + 40, read, true);
  };

  // Milestones of the boot
  const milestones = {};
  const core = rp.core;
  const clock = rp.clock;
  let phase = args.start === 'boot2' ? 1 : 0; // 0 ROM, 1 boot2, 2 image
  const boot2Entry = args.start === 'boot2' ? FLASH_BASE : BOOT2_SRAM;
  if (args.start === 'boot2') milestones.boot2_entered = 0;

  const BATCH = 200_000;
  let lastCheckPc = -1;
  let samePcBatches = 0;
  let idleCycles = 0;
  for (;;) {
    for (let i = 0; i < BATCH; i++) {
      if (core.waiting) {
        if (!clock.nextAlarm) {
          stopReason = 'wfi';
          break;
        }
        const nanos = Math.max(clock.nanosToNextAlarm, 0);
        const skipped = Math.ceil(nanos / NANOS_PER_CYCLE);
        clock.tick(skipped * NANOS_PER_CYCLE);
        cycles += skipped;
        idleCycles += skipped;
        continue;
      }
      const delta = core.executeInstruction();
      cycles += delta;
      instructions += 1;
      clock.tick(delta * NANOS_PER_CYCLE);
      const pc = core.PC;
      if (phase < 2) {
        if (phase === 0 && pc === boot2Entry) {
          milestones.boot2_entered = cycles;
          phase = 1;
        } else if (pc === resetVector) {
          milestones.reset_handler_entered = cycles;
          phase = 2;
        }
      }
      if (pc === renderEntry && milestones.render_entered === undefined) {
        milestones.render_entered = cycles;
        renderEnteredInstruction = instructions;
      }
      if (pc === hardFaultVector || pc === nmiVector) {
        const name = pc === hardFaultVector ? 'HardFault' : 'NMI';
        failure = `the core entered the ${name} handler at ${hex(pc)} (${symbolAt(elf, pc) ?? '?'}); LR ${hex(core.LR)}`;
        stopReason = 'fault';
        break;
      }
      if (stopReason) break;
    }
    pollRtt();
    if (stopReason) break;
    if (cycles >= args.maxCycles) {
      stopReason = 'max-cycles';
      failure = `reached --max-cycles ${args.maxCycles} at PC ${hex(core.PC)} (${symbolAt(elf, core.PC) ?? '?'}) without going idle`;
      break;
    }
    if (lastDisplayCycle >= 0 && cycles - lastDisplayCycle >= args.idleCycles) {
      stopReason = 'quiet';
      break;
    }
    // a `loop {}` (b .) never ends
    const pc = core.PC;
    if (pc === lastCheckPc && core.readUint16(pc & ~1) === 0xe7fe) {
      if (++samePcBatches >= 3) {
        stopReason = 'spin';
        break;
      }
    } else samePcBatches = 0;
    lastCheckPc = pc;
  }
  const wallMs = performance.now() - wallStart;
  if (phase === 0 && !failure) {
    failure = `the boot ROM never entered boot2 (PC ${hex(core.PC)}, ${symbolAt(elf, core.PC) ?? '?'})`;
  } else if (phase < 2 && !failure) {
    failure = `boot2 never reached the image's reset handler (PC ${hex(core.PC)})`;
  }

  // Outputs
  const outputs = {};
  const write = (suffix, data) => {
    const path = args.outPrefix + suffix;
    writeFileSync(path, data);
    outputs[suffix.slice(1)] = path;
  };
  let displaySummary;
  let drew = false;
  if (oled) {
    const pbmRowBytes = 16;
    const pbm = Buffer.alloc(64 * pbmRowBytes);
    for (let y = 0; y < 64; y++) {
      for (let x = 0; x < 128; x++) {
        if (!oled.lit(x, y)) pbm[y * pbmRowBytes + (x >> 3)] |= 0x80 >> (x & 7); // PBM 1 = black
      }
    }
    write('.pages.bin', oled.ram);
    write('.pbm', Buffer.concat([Buffer.from('P4\n128 64\n', 'latin1'), pbm]));
    write('.png', png(128, 64, 1, (x, y) => (oled.lit(x, y) ? 255 : 0), args.pngScale));
    write('.commands.json', JSON.stringify({ commands: oled.commandLog, flushes: oled.flushes }, null, 1));
    let litPixels = 0;
    for (let y = 0; y < 64; y++) for (let x = 0; x < 128; x++) litPixels += oled.lit(x, y);
    const initCommands = oled.commandLog.filter((c) => c.afterDataBytes === 0).map((c) => c.bytes);
    const s = oled.state;
    drew = oled.dataBytes > 0;
    displaySummary = {
      i2c_address: '0x3c',
      transactions: oled.transactions,
      control_bytes: oled.controlBytes,
      data_bytes: oled.dataBytes,
      commands_seen: oled.commandCounts,
      unknown_commands: oled.unknownCommands,
      init_commands: initCommands,
      addressing_mode: ['horizontal', 'vertical', 'page', 'invalid'][oled.addressingMode],
      flushes: oled.flushes.length,
      flush_windows: [...new Set(oled.flushes.map((f) => `columns ${f.columns?.join('-')}, pages ${f.pages?.join('-')}, ${f.bytes} bytes`))],
      pages_written: [...oled.pagesTouched].sort(),
      display_on: s.displayOn,
      contrast: s.contrast,
      inverted: s.inverted,
      entire_display_on: s.entireOn,
      segment_remap: s.segmentRemap,
      com_scan_remapped: s.comRemapped,
      start_line: s.startLine,
      display_offset: s.displayOffset,
      multiplex_ratio: s.multiplex + 1,
      com_pins: hex2(s.comPins),
      charge_pump: s.chargePump === null ? null : hex2(s.chargePump),
      lit_pixels: litPixels,
      blank: litPixels === 0 || litPixels === 128 * 64,
    };
  } else {
    const rgb = Buffer.alloc(240 * 240 * 2);
    const ppm = Buffer.alloc(240 * 240 * 3);
    const colours = new Set();
    let unwritten = 0;
    let renderRows = 0;
    for (let y = 0; y < 240; y++) {
      let rowAllTwice = true;
      for (let x = 0; x < 240; x++) {
        const v = panel.memory[y * 240 + x];
        colours.add(v);
        if (panel.written[y * 240 + x] === 0) unwritten++;
        if (panel.written[y * 240 + x] < 2) rowAllTwice = false;
        rgb.writeUInt16BE(v, (y * 240 + x) * 2);
        ppm.set(rgb565To888(v), (y * 240 + x) * 3);
      }
      if (rowAllTwice) renderRows++;
    }
    write('.rgb565', rgb);
    write('.ppm', Buffer.concat([Buffer.from('P6\n240 240\n255\n', 'latin1'), ppm]));
    write('.png', png(240, 240, 3, (x, y) => rgb565To888(panel.memory[y * 240 + x]), args.pngScale));
    write('.commands.json', JSON.stringify({ commands: panel.commandLog, windows: Object.fromEntries(panel.windows) }, null, 1));
    drew = panel.pixels > 0;
    const windows = [...panel.windows.entries()];
    displaySummary = {
      bytes: panel.bytes,
      ignored_bytes_cs_high_or_reset: bus.ignoredBytes,
      pixels_written: panel.pixels,
      pixels_outside_memory: panel.pixelsOutside,
      commands_seen: Object.fromEntries(Object.entries(panel.commandCounts).map(([k, v]) => [`${k} ${ST7789_NAMES[parseInt(k, 16)] ?? '?'}`, v])),
      unknown_commands: panel.unknownCommands,
      init_commands: panel.commandLog.slice(0, 12).map((c) => `${c.command} ${c.name} ${c.params}${c.pixels ? ` [${c.pixels} pixels]` : ''}`.trim()),
      hardware_reset_pulses: panel.hardwareResets,
      madctl: hex2(panel.madctl),
      colmod: hex2(panel.colmod),
      inversion_on: panel.inverted,
      sleeping: panel.sleeping,
      display_on: panel.displayOn,
      address_windows: windows.length,
      address_windows_first: windows.slice(0, 4).map(([k, v]) => `${k} x${v}`),
      address_windows_last: windows.slice(-2).map(([k, v]) => `${k} x${v}`),
      visible_pixels_never_written: unwritten,
      visible_rows_written_twice: renderRows,
      distinct_colours: colours.size,
      blank: colours.size <= 1,
    };
  }
  if (defmtChunks.length) write('.defmt.bin', Buffer.concat(defmtChunks));

  if (!failure && !drew) failure = `the image went idle (${stopReason}) without sending anything to the display`;
  const summary = {
    ok: !failure,
    failure: failure ?? undefined,
    display: args.display,
    elf: args.elf,
    rp2040js: RP2040JS_VERSION,
    start: args.start === 'rom' ? 'boot ROM reset vector' : 'boot2 at 0x10000000 (ROM boot path skipped)',
    stop_reason: stopReason,
    cycles_to_first_display_byte: firstDisplayCycle >= 0 ? firstDisplayCycle : null,
    cycles_to_last_display_byte: lastDisplayCycle >= 0 ? lastDisplayCycle : null,
    instructions_to_last_display_byte: lastDisplayInstruction >= 0 ? lastDisplayInstruction : null,
    instructions_to_render_entered: renderEnteredInstruction >= 0 ? renderEnteredInstruction : null,
    total_cycles: cycles,
    idle_cycles_skipped: idleCycles,
    emulated_ms_to_last_display_byte: lastDisplayCycle >= 0 ? +((lastDisplayCycle / CLOCK_HZ) * 1000).toFixed(3) : null,
    wall_ms: Math.round(wallMs),
    mcycles_per_wall_second: +(cycles / 1e6 / (wallMs / 1000)).toFixed(1),
    final_pc: hex(core.PC),
    final_function: symbolAt(elf, core.PC),
    boot: {
      milestones_cycles: milestones,
      boot2_crc_ok: boot2Crc === boot2CrcStored,
      flash_commands: serialFlash.commands,
      ssi_quad_frames: ssi.quadFrames,
      vector_table: { reset: hex(resetVector), hard_fault: hex(hardFaultVector) },
      loaded_segments: loaded,
    },
    bus: {
      nacks: bus.nacks,
      other_addresses: bus.otherAddresses,
      reads: bus.reads,
      pin_functions_at_first_transfer: bus.pinFunctions,
    },
    display_state: displaySummary,
    defmt_rtt_bytes: defmtBytes,
    defmt_log: defmtChunks.length ? decodeDefmt(Buffer.concat(defmtChunks), elf.defmt) : [],
    emulator_warnings: Object.keys(warningCounts).length ? warningCounts : undefined,
    outputs,
  };
  process.stdout.write(JSON.stringify(summary, null, 2) + '\n');
  if (failure) {
    process.stderr.write(`run-pico: ${failure}\n`);
    process.exit(1);
  }
}

function fail(message) {
  process.stderr.write(`run-pico: ${message}\n`);
  process.exit(1);
}

main();
