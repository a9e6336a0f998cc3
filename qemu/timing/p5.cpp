// The P5 model (p5.h). Sources, by the abbreviations of docs/cycles.md: BB19, BB20, BB21 (Abrash's
// Black Book: the Pentium's pipes, Tables 20.1 and 20.2, register contention, AGIs, prefixes);
// FM (Byggmastar's fatmap.txt and fatmap2.txt, for what the Black Book leaves out).
#include "qemu/timing/p5.h"

#include <algorithm>
#include <stdexcept>

namespace timing {

namespace {

bool mem_operand(const Insn& in) { return in.mem.present && !in.mem.stack; }
bool accesses_memory(const Insn& in) { return mem_operand(in) && in.mnemonic != "lea"; }
bool mem_dest(const Insn& in) { return accesses_memory(in) && in.mem.write; }
// An immediate and a displacement in one instruction: it cannot pair (BB20's Tables, BB21)
bool disp_and_imm(const Insn& in) { return in.has_imm && in.mem.has_disp && mem_operand(in); }
// prefix bytes that run alone in U, a cycle each: 66h, 67h, segment, LOCK, REP, and 0Fh but on a
// conditional jump (BB19, BB20)
int prefix_cycles(const Insn& in) {
    return int(in.opsize_prefix) + int(in.addrsize_prefix) + int(in.segment_prefix) + int(in.lock_prefix) + int(in.rep_prefix) +
           int(in.two_byte_opcode && in.kind != Kind::Jcc);
}

// The registers it writes that count for contention and AGIs: ESP changed by PUSH, POP, CALL and
// RET only implicitly does not (BB21, "Exceptions to Register Contention").
std::vector<RegPart> counted_writes(const Insn& in) {
    std::vector<RegPart> out;
    for (RegPart w : in.writes)
        if (w.family != Family::SP || in.writes_sp_explicitly) out.push_back(w);
    return out;
}
std::vector<RegPart> counted_reads(const Insn& in) {
    std::vector<RegPart> out;
    for (RegPart r : in.reads)
        if (r.family != Family::SP || !in.mem.stack) out.push_back(r);
    return out;
}

}  // namespace

Pairing P5::pairing(const Insn& in) {
    const std::string& m = in.mnemonic;
    const bool mem = mem_operand(in);
    if (in.kind == Kind::Jcc && !in.loop) return Pairing::PV;
    if (in.kind == Kind::Jmp || in.kind == Kind::Call) return Pairing::PV;
    if (disp_and_imm(in)) return Pairing::NP;
    if (among(m, {"mov", "add", "sub", "and", "or", "xor", "inc", "dec", "cmp", "lea", "nop"})) return Pairing::UV;
    if (m == "push" || m == "pop") return mem ? Pairing::NP : Pairing::UV;
    // TEST pairs with registers, or the accumulator and an immediate (BB20, Table 20.1)
    if (m == "test") {
        if (mem) return Pairing::NP;
        const bool imm = in.has_imm;
        const bool acc = std::all_of(in.reads.begin(), in.reads.end(), [](RegPart p) { return p.family == Family::A; });
        return !imm || acc ? Pairing::UV : Pairing::NP;
    }
    if (m == "adc" || m == "sbb") return Pairing::PU;
    if (among(m, {"shl", "sal", "shr", "sar"})) return !mem && (in.has_imm || in.opcode == 0xD0 || in.opcode == 0xD1) ? Pairing::PU : Pairing::NP;
    if (among(m, {"rol", "ror", "rcl", "rcr"})) return !mem && (in.opcode == 0xD0 || in.opcode == 0xD1) ? Pairing::PU : Pairing::NP;
    return Pairing::NP;
}

int P5::clocks(const Insn& in) {
    const std::string& m = in.mnemonic;
    const bool mem = accesses_memory(in), dest = mem_dest(in);
    if (among(m, {"mov", "lea", "nop", "neg", "not"})) return 1;  // BB20; FM (NEG: "non pairable, 1 tick")
    if (among(m, {"add", "sub", "and", "or", "xor", "adc", "sbb"})) return dest ? 3 : mem ? 2 : 1;  // BB20, Tables 20.1 and 20.2
    if (m == "cmp" || m == "test") return mem ? 2 : 1;                                           // BB20
    if (m == "inc" || m == "dec") return dest ? 3 : 1;                                           // BB19, BB20
    if (m == "push") return mem ? 2 : 1;                                                         // BB20
    if (m == "pop" && !mem) return 1;                                                            // BB20
    if (among(m, {"shl", "sal", "shr", "sar", "rol", "ror"}) && !mem) return in.opcode == 0xD2 || in.opcode == 0xD3 ? 4 : 1;  // BB20
    if ((m == "rcl" || m == "rcr") && !mem && (in.opcode == 0xD0 || in.opcode == 0xD1)) return 1;                         // BB20
    if (in.kind == Kind::Jcc && !in.loop) return 1;  // predicted (BB19)
    if (in.kind == Kind::Jmp || in.kind == Kind::Call) return 1;
    throw std::runtime_error("no Pentium timing for '" + in.text + "' (docs/cycles.md lists what the model knows)");
}

std::vector<P5Issue> P5::run(const std::vector<Executed>& stream) {
    std::vector<P5Issue> out(stream.size());
    std::array<long, size_t(Family::Count)> written;  // the cycle a write of each family ended in
    written.fill(-1000);
    std::map<uint32_t, int> btb;  // a branch's two-bit counter: taken predicted from 2 up
    auto predicted = [&](const Insn& in) {
        const auto it = btb.find(in.address);
        return it != btb.end() && it->second >= 2;  // (not in the buffer: not taken)
    };
    auto learn = [&](const Insn& in, bool taken) {
        const auto it = btb.find(in.address);
        if (it == btb.end()) {
            if (taken) btb[in.address] = 3;  // enters taken
            return;
        }
        it->second = std::clamp(it->second + (taken ? 1 : -1), 0, 3);
    };
    // the cycle its address registers are ready in (written two cycles before, BB21); PUSH and POP
    // address through ESP, which counts only as written explicitly (`written` keeps no other)
    auto ready = [&](const Insn& in, Family* on) {
        long r = -1000;
        if (!in.mem.present) return r;
        for (Family f : {in.mem.base, in.mem.index})
            if (f != Family::None && written[size_t(f)] + 2 > r) r = written[size_t(f)] + 2, *on = f;
        return r;
    };
    auto branch_clocks = [&](const Insn& in, bool taken, char pipe, std::vector<std::string>* stalls) {
        if (in.kind != Kind::Jcc && in.kind != Kind::Jmp && in.kind != Kind::Call) return clocks(in);
        const bool right = in.kind == Kind::Jcc ? predicted(in) == taken : btb.count(in.address) > 0;
        learn(in, taken || in.kind != Kind::Jcc);
        if (right) return 1;
        const int c = in.kind != Kind::Jcc ? 3 : pipe == 'U' ? 4 : 5;  // BB19, BB21
        stalls->push_back("mispredicted +" + std::to_string(c - 1));
        return c;
    };

    long now = 0;
    for (size_t i = 0; i < stream.size();) {
        const Insn& u = *stream[i].insn;
        P5Issue& iu = out[i];
        Family agi_on = Family::None;
        const long agi_ready = ready(u, &agi_on);
        const int prefixes = prefix_cycles(u);
        const long wait = std::max<long>(0, agi_ready - now);
        const long start = now + std::max<long>(wait, prefixes);  // (a prefix decodes while an AGI waits: BB19)
        if (wait) iu.stalls.push_back(std::string("AGI on ") + family_name(agi_on) + " +" + std::to_string(wait));
        if (prefixes > wait) iu.stalls.push_back("prefix +" + std::to_string(prefixes - wait));

        // the next pairs with it in V: both pairable their ways, no prefix on the second, neither
        // writing what the other reads or writes but the flags a branch reads and two flag writers
        // (BB20, BB21)
        bool pair = false;
        std::string why_not;
        if (i + 1 < stream.size()) {
            const Insn& v = *stream[i + 1].insn;
            const Pairing pu = pairing(u), pv = pairing(v);
            Family v_on = Family::None;
            const bool contention = [&] {
                for (RegPart w : counted_writes(u)) {
                    for (RegPart r : counted_reads(v))
                        if (r.family == w.family) return true;
                    for (RegPart x : counted_writes(v))
                        if (x.family == w.family) return true;
                }
                return u.writes_flags && v.reads_flags && v.kind != Kind::Jcc;
            }();
            pair = (pu == Pairing::UV || pu == Pairing::PU) && (pv == Pairing::UV || pv == Pairing::PV) && prefix_cycles(v) == 0 && !contention &&
                   ready(v, &v_on) <= start;
        }
        int cu = branch_clocks(u, stream[i].taken, 'U', &iu.stalls), cycles = cu;
        if (pair) {
            const Insn& v = *stream[i + 1].insn;
            P5Issue& iv = out[i + 1];
            const int cv = branch_clocks(v, stream[i + 1].taken, 'V', &iv.stalls);
            // lockstep; two memory-destination instructions overlap a cycle only (BB20)
            cycles = mem_dest(u) && mem_dest(v) ? cu + cv - 1 : std::max(cu, cv);
            // the same bank of the data cache (address bits 2-4) where the code tells: the same
            // registers, displacements in the same dword of the 32 bytes (BB20)
            if (accesses_memory(u) && accesses_memory(v) && u.mem.base == v.mem.base && u.mem.index == v.mem.index && u.mem.scale == v.mem.scale &&
                ((u.mem.disp >> 2) & 7) == ((v.mem.disp >> 2) & 7)) {
                ++cycles;
                iv.stalls.push_back("bank conflict +1");
            }
            iv.cycle = start, iv.pipe = 'V', iv.clocks = cycles;
        }
        iu.cycle = start, iu.pipe = 'U', iu.clocks = cycles;
        const long end = start + cycles - 1;
        for (size_t k = i; k < i + (pair ? 2 : 1); ++k)
            for (RegPart w : counted_writes(*stream[k].insn)) written[size_t(w.family)] = end;
        now = start + cycles;
        i += pair ? 2 : 1;
    }
    return out;
}

}  // namespace timing
