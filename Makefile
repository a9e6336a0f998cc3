# modexlab: the kernel (freestanding i686 C++ and NASM), its ISO, the host harness and the tests.
#   make all    kernel ELF + ISO            make run    boot in QEMU, play the demo scenes, save screenshots
#                                           (builds only the kernel and the harness)
#   make test   every test, one summary      make clean  remove build/
#   make bench  the speed/accuracy report (build/report), then the gallery
#   make gallery every mapper's picture beside its error map, a page a scene (build/gallery)
#   make test-gallery  the gallery's pages in a headless Chromium (installs Debian's chromium)
#   make bounds the error bounds against measured errors on 100000 random polygons a mapper
#   make fuzz   every mapper over 10^6 random polygons under the sanitizers, the parsers under libFuzzer
#   make extremes  every mapper through the classes of extreme input: build/report/extremes.md
#   make deps   install missing tools (run, bench and test install what they need themselves)

MAKEFLAGS += -rR --no-print-directory
.SUFFIXES:
.DELETE_ON_ERROR:
SHELL := /bin/bash
V ?= 0
Q := $(if $(filter 1,$(V)),,@)
say = $(if $(filter 1,$(V)),,@echo "  $(1)	$(2)")

BUILD := build
KBUILD := $(BUILD)/kernel
HBUILD := $(BUILD)/host

# ---- tools -------------------------------------------------------------------------------------

CROSS := $(if $(shell command -v i686-elf-g++ 2>/dev/null),i686-elf-,i686-linux-gnu-)
KCXX := $(CROSS)g++
NASM := nasm
HCXX := g++
NPROC := $(shell nproc 2>/dev/null || echo 2)
SUDO := $(if $(filter 0,$(shell id -u)),,sudo)

# What must be on the machine -> the Debian package that brings it, by what needs it: the kernel
# and the host tools (BUILD), make run (QEMU besides), make bench (its plots besides), and all the
# rest: the ISO, the tests (GoogleTest, the 32-bit programs' emulator, Bochs, UEFI firmware, zbar).
# `make deps` installs everything; a target that needs less asks for less (DEPS_FOR).
DEPS_BUILD := \
	nasm:nasm \
	grub-file:grub-common \
	g++:g++ \
	/usr/include/nlohmann/json.hpp:nlohmann-json3-dev \
	/usr/include/png.h:libpng-dev \
	/usr/include/capstone/capstone.h:libcapstone-dev \
	i686-linux-gnu-g++:g++-i686-linux-gnu \
	/usr/share/games/doom/freedoom1.wad:freedoom
DEPS_RUN := $(DEPS_BUILD) qemu-system-i386:qemu-system-x86
# (make run DISPLAY=1: QEMU's GTK window, a module of its own package)
DEPS_DISPLAY := $(DEPS_RUN) /usr/lib/$(shell uname -m)-linux-gnu/qemu/ui-gtk.so:qemu-system-gui
DEPS_BENCH := $(DEPS_RUN) gnuplot:gnuplot-nox
DEPS_ALL := $(DEPS_BENCH) $(filter-out $(DEPS_RUN),$(DEPS_DISPLAY)) Xvfb:xvfb \
	grub-mkrescue:grub-common \
	/usr/lib/grub/i386-pc/multiboot.mod:grub-pc-bin \
	xorriso:xorriso \
	mformat:mtools \
	/usr/include/gtest/gtest.h:libgtest-dev \
	/usr/src/googletest/googletest/src/gtest-all.cc:googletest \
	qemu-i386:qemu-user \
	zbarimg:zbar-tools \
	bochs-bin:bochs \
	/usr/share/bochs/BIOS-bochs-latest:bochsbios \
	/usr/share/vgabios/vgabios.bin:vgabios \
	/usr/lib/grub/x86_64-efi/multiboot.mod:grub-efi-amd64-bin \
	/usr/lib/grub/i386-efi/multiboot.mod:grub-efi-ia32-bin \
	/usr/share/ovmf/OVMF.fd:ovmf \
	/usr/share/OVMF/OVMF32_CODE_4M.secboot.fd:ovmf-ia32
DEPS_FOR ?= ALL

# ---- kernel ------------------------------------------------------------------------------------

KERNEL := $(KBUILD)/modexlab.elf
ISO := $(BUILD)/modexlab.iso

LOOP_ASM := $(wildcard asm/*.asm)
KERNEL_ASM := boot/entry.asm boot/isr.asm $(LOOP_ASM)
# the portable core, the mappers and the scene code, built for the kernel and the host alike
PORTABLE_DIRS := kernel/core kernel/mappers kernel/mappers/auto kernel/scene
KERNEL_CXX := $(wildcard kernel/*.cpp kernel/platform/*.cpp kernel/present/*.cpp kernel/show/*.cpp kernel/lib/*.cpp kernel/server/*.cpp $(PORTABLE_DIRS:%=%/*.cpp) drivers/*.cpp)
# One kernel for every PC from the 486 on: its C++ is built for the 486 (KARCH), and built again for
# the P6 (P6ARCH: CMOV, FCOMI), which runs where CPUID reports CMOV (kernel/platform/isa.h). Each
# build is bundled (ld -r) with its constructors in a section of its own, the P6 one with every
# symbol it defines renamed p6.NAME. The drivers, kernel/platform (the IRQs' state, the CPU's, the
# pool) and the replies' sequence counter (the exception handler replies too) are built once, for
# the 486, and serve both.
KARCH := -march=i486 -mtune=generic
P6ARCH := -march=i686 -mtune=i686
# (the objects depend on the file that records both: a change to either rebuilds them)
ARCH_FILE := $(KBUILD)/arch.txt
$(shell mkdir -p $(KBUILD) && { echo '$(KARCH) / $(P6ARCH)' | cmp -s - $(ARCH_FILE) || echo '$(KARCH) / $(P6ARCH)' >$(ARCH_FILE); })
SHARED_CXX := $(filter drivers/% kernel/platform/% kernel/server/reply.cpp,$(KERNEL_CXX))
TWICE_CXX := $(filter-out $(SHARED_CXX),$(KERNEL_CXX))
I486_BUNDLE := $(KBUILD)/i486.bundle.o
P6_BUNDLE := $(KBUILD)/p6.bundle.o
# (the P6 bundle has the NASM loops too, assembled with -DP6: min and max by CMOV, asm/loop.inc)
P6_LOOP_OBJS := $(LOOP_ASM:%=$(KBUILD)/p6/%.o)
KERNEL_OBJS := $(KERNEL_ASM:%=$(KBUILD)/%.o) $(SHARED_CXX:%=$(KBUILD)/%.o) $(I486_BUNDLE) $(P6_BUNDLE)

# The built-in files: the demo scenes, and the freedoom scene's textures made at build time from
# Debian's freedoom WAD (not committed). Each is named by its path under scenes/ or build/scenes/.
DEMO_SCENES := $(wildcard scenes/*.scene)
FREEDOOM_WAD := /usr/share/games/doom/freedoom1.wad
FREEDOOM_DIR := $(BUILD)/scenes/freedoom
FREEDOOM_NAMES := floor0_1 ceil3_5 startan3 comptall brown1
FREEDOOM_TEXTURES := $(FREEDOOM_NAMES:%=$(FREEDOOM_DIR)/%.bmp)
BUILTIN_SOURCES := $(DEMO_SCENES) $(FREEDOOM_TEXTURES)
BUILTIN_ASM := $(KBUILD)/gen/builtin.asm
KERNEL_OBJS += $(BUILTIN_ASM).o

WARNINGS := -Wall -Wextra -Werror -Wshadow -Wnon-virtual-dtor -Wcast-align -Wundef
# '=': expanded when a recipe runs, after `deps` may have installed the cross compiler
# -ffp-contract=off (all builds): no fused multiply-adds, so double arithmetic rounds the same on
# the host (SSE2) and in the kernel (x87 at 53-bit precision, set in boot/entry.asm). -fno-math-errno:
# a square root is the instruction (sqrtsd, fsqrt: correctly rounded on both), not a libm call.
KCXXFLAGS_NODEP = -std=c++20 -m32 $(KARCH) -O2 -g $(WARNINGS) -ffp-contract=off -fno-math-errno -DMODEXLAB_ASM_LOOPS \
	-ffreestanding -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit \
	-fno-stack-protector -fno-pic -fno-pie -fno-asynchronous-unwind-tables -fno-omit-frame-pointer \
	-nostdinc -isystem $(shell $(KCXX) -print-file-name=include 2>/dev/null) -I.
KCXXFLAGS = $(KCXXFLAGS_NODEP) -MMD -MP
KLDFLAGS := -m32 -nostdlib -static -no-pie -T boot/linker.ld -Wl,--build-id=none -Wl,-z,noexecstack \
	-Wl,--fatal-warnings -Wl,--no-warn-rwx-segments
NASMFLAGS := -f elf32 -g -F dwarf -w+all -w+error -I$(KBUILD)/gen/ -Iasm/

# ---- host --------------------------------------------------------------------------------------

# portable kernel code the host builds too (no port I/O, no inline asm)
CORE_CXX := $(wildcard $(PORTABLE_DIRS:%=%/*.cpp))
PORTABLE_CXX := kernel/lib/words.cpp kernel/lib/keys.cpp kernel/lib/qr.cpp kernel/lib/protocol.cpp kernel/lib/encode.cpp kernel/lib/json.cpp kernel/lib/fmt.cpp kernel/lib/stats.cpp $(CORE_CXX)
# host-only code: the exact reference and the accuracy measures, the harness, the tools' libraries
HARNESS_CXX := $(filter-out %/main.cpp %_main.cpp,$(wildcard qemu/*/*.cpp))
HARNESS_OBJS := $(HARNESS_CXX:%=$(HBUILD)/%.o) $(PORTABLE_CXX:%=$(HBUILD)/%.o)
TEST_CXX := $(wildcard tests/*.cpp tests/unit/*.cpp tests/unit/*/*/*.cpp tests/system/*.cpp)

HCXXFLAGS := -std=c++20 -O2 -g $(WARNINGS) -ffp-contract=off -fno-math-errno -I. -MMD -MP
# (the host objects and the tests' precompiled header depend on the file that records the flags)
HFLAGS_FILE := $(HBUILD)/flags.txt
$(shell mkdir -p $(HBUILD) && { echo '$(HCXXFLAGS)' | cmp -s - $(HFLAGS_FILE) || echo '$(HCXXFLAGS)' >$(HFLAGS_FILE); })
HLDLIBS := -lpng -lpthread -lcapstone

# 32-bit static host programs: the NASM loops against their C++ twins (tests/asm), with GoogleTest
# built from Debian's sources for i686
H32BUILD := $(BUILD)/host32
H32CXX := i686-linux-gnu-g++
GTEST_SRC := /usr/src/googletest/googletest
H32CXXFLAGS = -std=c++20 -m32 $(KARCH) -O2 -g $(WARNINGS) -ffp-contract=off -fno-math-errno -DMODEXLAB_ASM_LOOPS -I. \
	-isystem $(GTEST_SRC)/include -MMD -MP
ASM_TESTS := $(H32BUILD)/modexlab-asm-tests
# runs them natively where this machine can, else under qemu-i386 (qemu/tools/run32); its probe
RUN32 := $(H32BUILD)/run32
NATIVE32 := $(H32BUILD)/modexlab-native32
# real host cycles of the mappers, C++ twins and NASM loops, 32-bit static (modexlab-bench runs it)
CYCLES := $(H32BUILD)/modexlab-cycles
CYCLES_CXX := qemu/tools/cycles_main.cpp
ASM_TEST_CXX := tests/main.cpp $(wildcard tests/asm/*.cpp)
# the portable code they run is the kernel's own objects (the same -m32 -march and flags, linked
# against the C library here): the 32-bit programs test and time the very code the kernel runs
PORTABLE32_OBJS := $(patsubst %,$(KBUILD)/%.o,kernel/lib/words.cpp kernel/lib/keys.cpp kernel/lib/fmt.cpp $(CORE_CXX)) $(LOOP_ASM:%=$(KBUILD)/%.o)

HARNESS := $(HBUILD)/modexlab
RENDER := $(HBUILD)/modexlab-render
WAD := $(HBUILD)/modexlab-wad
SCENE_TOOL := $(HBUILD)/modexlab-scene
BENCH := $(HBUILD)/modexlab-bench
GALLERY := $(HBUILD)/modexlab-gallery
EXTREMES := $(HBUILD)/modexlab-extremes
# the cycle-timing model's static analyser (qemu/timing, docs/cycles.md), and the model as a QEMU
# plugin for whole frames (qemu/plugin), its objects built position-independent
TIMING := $(HBUILD)/modexlab-timing
TIMING_PLUGIN := $(HBUILD)/libmodexlab-timing.so
TIMING_PLUGIN_CXX := qemu/plugin/plugin_main.cpp $(wildcard qemu/timing/*.cpp)
# make profile's plugin and tool (qemu/plugin, qemu/tools; docs/bench.md, "Where the instructions go")
PROFILE_PLUGIN := $(HBUILD)/libmodexlab-profile.so
PROFILE := $(HBUILD)/modexlab-profile
TESTS := $(HBUILD)/modexlab-tests
# the unit tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer
SBUILD := $(BUILD)/host-san
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# -O1 (what ASan advises) and line tables only: half the compile time of -O2 -g, the reports still
# name file and line
SAN_CXXFLAGS := -O1 -g1
SAN_TESTS := $(SBUILD)/modexlab-unit-tests-san
UNIT_CXX := tests/main.cpp $(wildcard tests/unit/*.cpp tests/unit/*/*/*.cpp)
# the gallery's pages in a headless browser (make test-gallery, a tier of its own)
BROWSER_TESTS := $(HBUILD)/modexlab-browser-tests
BROWSER_TEST_CXX := tests/main.cpp $(wildcard tests/browser/*.cpp)
# the fuzz targets (tests/fuzz, one per parser of outside input): the replay program runs each over
# its committed corpus under the sanitizers (make test); `make fuzz` builds each as a libFuzzer
# program with Debian's clang and runs it
FUZZ_TARGETS := $(patsubst tests/fuzz/%_fuzz.cpp,%,$(wildcard tests/fuzz/*_fuzz.cpp))
FUZZ_REPLAY := $(SBUILD)/modexlab-fuzz-replay
FUZZ_COMMON_CXX := tests/fuzz/fuzz.cpp $(FUZZ_TARGETS:%=tests/fuzz/%_fuzz.cpp)
FBUILD := $(BUILD)/fuzz
FUZZ_CXX := clang++
FUZZ_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g
FUZZERS := $(FUZZ_TARGETS:%=$(FBUILD)/fuzz-%)
# a Multiboot kernel that enters modexlab with a wrong magic (tests/fixtures)
WRONG_MAGIC_LOADER := $(KBUILD)/tests/wrong_magic_loader.elf

# ---- targets -----------------------------------------------------------------------------------

.PHONY: all iso kernel host fixtures usb run bench test-bochs test-cpu report gallery bounds extremes fuzz fuzz-corpus fuzz-protocol soak test test-gallery deps clean listing profile
all: $(KERNEL) $(ISO)
kernel: $(KERNEL)
iso: $(ISO)
host: $(HARNESS) $(RENDER) $(WAD) $(SCENE_TOOL) $(BENCH) $(GALLERY) $(EXTREMES) $(TIMING) $(TIMING_PLUGIN) $(PROFILE_PLUGIN) $(PROFILE) $(CYCLES) $(TESTS) $(SAN_TESTS) $(ASM_TESTS) $(RUN32) $(FUZZ_REPLAY)
fixtures: $(WRONG_MAGIC_LOADER)

# $(call install,FILE:PACKAGE ...): installs the packages whose file or command is missing.
define install
	@missing=""; \
	for pair in $(1); do \
		f="$${pair%%:*}"; p="$${pair#*:}"; \
		case "$$f" in /*) [ -e "$$f" ] ;; *) command -v "$$f" >/dev/null ;; esac || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
		echo "deps: installing$$missing (log: $(BUILD)/deps.log)"; \
		mkdir -p $(BUILD); \
		{ $(SUDO) apt-get update -qq && \
		  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
		} >$(BUILD)/deps.log 2>&1 || { cat $(BUILD)/deps.log; echo "deps: apt-get failed"; exit 1; }; \
	fi
endef

deps:
	$(call install,$(DEPS_$(DEPS_FOR)))

# The 486 runs it: a P6 instruction (CMOV, FCMOV, FCOMI, FUCOMI) outside the P6 build's functions
# (p6.NAME) fails the link, the function and the instruction named.
P6_ONLY := cmov|fcmov|fcomi|fucomi
$(KERNEL): $(KERNEL_OBJS) boot/linker.ld
	$(call say,LD,$@)
	$(Q)$(KCXX) $(KLDFLAGS) -o $@.tmp $(KERNEL_OBJS) -lgcc
	@grub-file --is-x86-multiboot $@.tmp || { echo "$@: not a Multiboot v1 kernel"; rm -f $@.tmp; exit 1; }
	@$(CROSS)objdump -d --no-show-raw-insn $@.tmp | awk '/^[0-9a-f]+ <.*>:$$/ { fn = $$0 } \
		$$2 ~ /^($(P6_ONLY))/ && fn !~ /^[0-9a-f]+ <p6\./ { print fn " " $$2; bad = 1 } END { exit bad }' || \
		{ echo "$@: P6 instructions above outside the P6 build, which a 486 does not have"; rm -f $@.tmp; exit 1; }
	@mv $@.tmp $@

$(KBUILD)/%.cpp.o: %.cpp $(ARCH_FILE) | deps
	@mkdir -p $(@D)
	$(call say,KCXX,$<)
	$(Q)$(KCXX) $(KCXXFLAGS) -c $< -o $@

$(KBUILD)/p6/%.cpp.o: %.cpp $(ARCH_FILE) | deps
	@mkdir -p $(@D)
	$(call say,KCXX-P6,$<)
	$(Q)$(KCXX) $(KCXXFLAGS) $(P6ARCH) -c $< -o $@

# bundle(objects, constructors' section, rename): ld -r, the constructors moved to their section (or
# left where they are: -), and with `rename`, every symbol the bundle defines (its locals too) renamed p6.NAME
define bundle
	@mkdir -p $(@D)
	$(call say,BUNDLE,$@)
	$(Q)$(CROSS)ld -m elf_i386 -r -z noexecstack -o $@.tmp $(1)
	$(Q)$(if $(3),$(CROSS)nm -P --defined-only $@.tmp | awk '!seen[$$1]++ { print $$1 " p6." $$1 }' >$@.syms,: >$@.syms)
	$(Q)$(CROSS)objcopy --redefine-syms=$@.syms $(if $(filter -,$(2)),,--rename-section .init_array=$(2)) $@.tmp $@
	@rm -f $@.tmp
endef
$(I486_BUNDLE): $(TWICE_CXX:%=$(KBUILD)/%.o)
	$(call bundle,$^,.i486_init_array,)
$(P6_BUNDLE): $(TWICE_CXX:%=$(KBUILD)/p6/%.o) $(P6_LOOP_OBJS)
	$(call bundle,$^,.p6_init_array,rename)

# asm/NAME.asm reads the layouts of gen/NAME.inc, made from the offsets its C++ home lists under
# MODEXLAB_OFFSETS: kernel/mappers/NAME.cpp for a family, kernel/core/NAME.cpp for core's types
# (CORE_INC, which every loop may read)
CORE_INC := $(addprefix $(KBUILD)/gen/,setup.inc walk.inc surface.inc envelope.inc)
define OFFSETS_RULE
$(KBUILD)/gen/%.inc: $(1)/%.cpp | deps
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)
	$$(Q)$$(KCXX) $$(KCXXFLAGS_NODEP) -DMODEXLAB_OFFSETS -MMD -MP -MF $$@.d -MT $$@ -S -o - $$< \
		| sed -n 's/.*@@@ \([A-Za-z0-9_]*\) \([0-9]*\).*/%define \1 \2/p' > $$@
	@test -s $$@ || { echo "$$@: no offsets generated ($(1)/$$*.cpp lists them under MODEXLAB_OFFSETS)"; rm -f $$@; exit 1; }
endef
$(eval $(call OFFSETS_RULE,kernel/mappers))
$(eval $(call OFFSETS_RULE,kernel/core))

$(LOOP_ASM:asm/%.asm=$(KBUILD)/p6/asm/%.asm.o): $(KBUILD)/p6/asm/%.asm.o: $(KBUILD)/gen/%.inc $(CORE_INC)
$(LOOP_ASM:asm/%.asm=$(KBUILD)/asm/%.asm.o): $(KBUILD)/asm/%.asm.o: $(KBUILD)/gen/%.inc $(CORE_INC)

# The NASM runs on a 486: an object with a P6 instruction (CMOV, FCMOV, FCOMI, FUCOMI) is refused.
# NASM 2.16.01's -MD lists no %include, so every object depends on every asm/*.inc.
ASM_INC := $(wildcard asm/*.inc)
$(KBUILD)/%.asm.o: %.asm $(ASM_INC) | deps
	@mkdir -p $(@D)
	$(call say,NASM,$<)
	$(Q)$(NASM) $(NASMFLAGS) -MD $(@:.o=.d) -MT $@ -MP $< -o $@
	@if $(CROSS)objdump -d $@ | grep -iE '[[:space:]](cmov|fcmov|fcomi|fucomi)'; then \
		echo "$<: P6 instructions above, which a 486 does not have"; rm -f $@; exit 1; fi

$(KBUILD)/p6/%.asm.o: %.asm $(ASM_INC) | deps
	@mkdir -p $(@D)
	$(call say,NASM-P6,$<)
	$(Q)$(NASM) $(NASMFLAGS) -DP6 -MD $(@:.o=.d) -MT $@ -MP $< -o $@

$(FREEDOOM_TEXTURES) &: $(WAD) | deps
	$(call say,WAD,$(FREEDOOM_DIR))
	$(Q)$(WAD) $(FREEDOOM_WAD) $(FREEDOOM_DIR) $(FREEDOOM_NAMES) >/dev/null

$(BUILTIN_ASM): $(BUILTIN_SOURCES) Makefile
	@mkdir -p $(@D)
	$(call say,GEN,$@)
	$(Q){ echo "; The kernel's built-in files (generated by the Makefile): name, data, size."; \
	  echo "section .rodata"; echo "align 4"; echo "global builtin_files, builtin_file_count"; \
	  echo "builtin_file_count: dd $(words $(BUILTIN_SOURCES))"; echo "builtin_files:"; \
	  i=0; for f in $(BUILTIN_SOURCES); do echo "    dd name_$$i, data_$$i, data_$${i}_end - data_$$i"; i=$$((i+1)); done; \
	  i=0; for f in $(BUILTIN_SOURCES); do n=$${f#scenes/}; n=$${n#$(BUILD)/scenes/}; \
	    echo "name_$$i: db \"$$n\", 0"; echo "data_$$i: incbin \"$$f\""; echo "data_$${i}_end:"; i=$$((i+1)); done; } > $@

$(BUILTIN_ASM).o: $(BUILTIN_ASM)
	$(call say,NASM,$<)
	$(Q)$(NASM) -f elf32 -w+all -w+error $< -o $@

$(WRONG_MAGIC_LOADER): $(KBUILD)/tests/fixtures/wrong_magic_loader.asm.o
	$(call say,LD,$@)
	$(Q)$(CROSS)ld -m elf_i386 -e start -Ttext=0x6000000 -z noexecstack -o $@ $<
	@grub-file --is-x86-multiboot $@ || { echo "$@: not a Multiboot v1 kernel"; rm -f $@; exit 1; }

# The ISO: the kernel, every built-in file again as a module under /boot/files (the kernel prefers a
# module to a built-in of the same name, so files on a USB stick can be changed without a rebuild),
# and a menu entry per demo scene loading just that scene and the files it names. GRUB's own files
# go in uncompressed: the ISO is rebuilt at every kernel change, and compressing them would be most of that.
# The kernel goes in without its debug sections (its symbols kept): GRUB reads the whole file, and
# in 16 MiB its heap has no room for them beside the image.
$(ISO): $(KERNEL) boot/grub.cfg $(BUILTIN_SOURCES)
	$(call say,ISO,$@)
	$(Q)rm -rf $(BUILD)/isodir && mkdir -p $(BUILD)/isodir/boot/grub $(BUILD)/isodir/boot/files
	$(Q)objcopy --strip-debug $(KERNEL) $(BUILD)/isodir/boot/modexlab.elf
	$(Q)for f in $(BUILTIN_SOURCES); do n=$${f#scenes/}; n=$${n#$(BUILD)/scenes/}; \
		mkdir -p $(BUILD)/isodir/boot/files/$$(dirname $$n); cp $$f $(BUILD)/isodir/boot/files/$$n; done
	$(Q)modules=""; entries=""; \
	for f in $(BUILTIN_SOURCES); do n=$${f#scenes/}; n=$${n#$(BUILD)/scenes/}; \
		modules="$$modules    module /boot/files/$$n $$n\n"; done; \
	for f in $(DEMO_SCENES); do n=$${f#scenes/}; s=$${n%.scene}; \
		entries="$$entries""menuentry \"modexlab: $$s\" {\n    multiboot /boot/modexlab.elf boot=demo scene=$$n\n    module /boot/files/$$n $$n\n"; \
		for t in $$(sed -n 's/^texture [^ ]* file \([^ ]*\).*/\1/p' $$f); do entries="$$entries    module /boot/files/$$t $$t\n"; done; \
		entries="$$entries    set gfxpayload=\$${modexlab_payload}\n    boot\n}\n\n"; done; \
	awk -v modules="$$(printf "$$modules")" -v scenes="$$(printf "$$entries")" \
		'/^@MODULES@$$/ { print modules; next } /^@SCENES@$$/ { print scenes; next } { print }' boot/grub.cfg \
		> $(BUILD)/isodir/boot/grub/grub.cfg
	$(Q)grub-mkrescue -o $@ $(BUILD)/isodir 2>$(BUILD)/grub-mkrescue.log || { cat $(BUILD)/grub-mkrescue.log; exit 1; }

$(HBUILD)/%.cpp.o: %.cpp $(HFLAGS_FILE) | deps
	@mkdir -p $(@D)
	$(call say,CXX,$<)
	$(Q)$(HCXX) $(HCXXFLAGS) -c $< -o $@

$(HBUILD)/pic/%.cpp.o: %.cpp $(HFLAGS_FILE) | deps
	@mkdir -p $(@D)
	$(call say,CXX-PIC,$<)
	$(Q)$(HCXX) $(HCXXFLAGS) -fPIC -fvisibility=hidden -c $< -o $@

$(TIMING_PLUGIN): $(TIMING_PLUGIN_CXX:%=$(HBUILD)/pic/%.o)
$(PROFILE_PLUGIN): $(HBUILD)/pic/qemu/plugin/profile_plugin_main.cpp.o
$(TIMING_PLUGIN) $(PROFILE_PLUGIN):
	$(call say,LINK,$@)
	$(Q)$(HCXX) -shared -o $@ $^ -lcapstone

# The tests' heavy headers parsed once: tests/pch.h precompiled, and taken first by every test
# object (-include; -Winvalid-pch says when one does not fit the flags). The tests' own code at
# -O1 with line tables only (-g1): less than two thirds of the compile time at -O2 -g; the code
# under test keeps -O2, and failures and backtraces still name lines.
TEST_FLAGS := -O1 -g1
TEST_PCH := $(HBUILD)/pch/tests.h
$(TEST_PCH).gch: tests/pch.h $(HFLAGS_FILE) | deps
	@mkdir -p $(@D)
	$(call say,PCH,$<)
	$(Q)cp $< $(TEST_PCH)
	$(Q)$(HCXX) $(HCXXFLAGS) $(TEST_FLAGS) -x c++-header $(TEST_PCH) -o $@
$(HBUILD)/tests/%.cpp.o: HCXXFLAGS += $(TEST_FLAGS) -include $(TEST_PCH) -Winvalid-pch -Wno-error=invalid-pch
$(patsubst %,$(HBUILD)/%.o,$(filter tests/%,$(TEST_CXX) $(UNIT_CXX) $(BROWSER_TEST_CXX))): $(TEST_PCH).gch

$(HARNESS): $(HBUILD)/qemu/harness/main.cpp.o $(HARNESS_OBJS)
	$(call say,LINK,$@)
	$(Q)$(HCXX) -o $@ $^ $(HLDLIBS)

# the host tools: modexlab-NAME from qemu/tools/NAME_main.cpp (objects kept)
.SECONDARY: $(patsubst %,$(HBUILD)/%.o,$(wildcard qemu/tools/*_main.cpp))
$(HBUILD)/modexlab-%: $(HBUILD)/qemu/tools/%_main.cpp.o $(HARNESS_OBJS)
	$(call say,LINK,$@)
	$(Q)$(HCXX) -o $@ $^ $(HLDLIBS)

$(SBUILD)/%.cpp.o: %.cpp | deps
	@mkdir -p $(@D)
	$(call say,CXX-SAN,$<)
	$(Q)$(HCXX) $(HCXXFLAGS) $(SAN_FLAGS) $(SAN_CXXFLAGS) -c $< -o $@

# The unit tests' own code is the plain build's: the sanitizers check the code under test, linked
# first so that the inline functions both compile are its instrumented copies.
$(SAN_TESTS): $(HARNESS_CXX:%=$(SBUILD)/%.o) $(PORTABLE_CXX:%=$(SBUILD)/%.o) $(UNIT_CXX:%=$(HBUILD)/%.o)
	$(call say,LINK,$@)
	$(Q)$(HCXX) $(SAN_FLAGS) -o $@ $^ -lgtest $(HLDLIBS)

# where the replay program finds the committed corpora
$(SBUILD)/tests/fuzz/replay_main.cpp.o: HCXXFLAGS += -DMODEXLAB_SOURCE_DIR='"$(abspath .)"'
$(FUZZ_REPLAY): $(SBUILD)/tests/fuzz/replay_main.cpp.o $(FUZZ_COMMON_CXX:%=$(SBUILD)/%.o) $(HARNESS_CXX:%=$(SBUILD)/%.o) $(PORTABLE_CXX:%=$(SBUILD)/%.o)
	$(call say,LINK,$@)
	$(Q)$(HCXX) $(SAN_FLAGS) -o $@ $^ $(HLDLIBS)

# libFuzzer programs: everything instrumented for coverage (fuzzer-no-link), one program a target
$(FBUILD)/%.cpp.o: %.cpp | deps
	@mkdir -p $(@D)
	$(call say,CLANG,$<)
	$(Q)$(FUZZ_CXX) $(HCXXFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -DMODEXLAB_LIBFUZZER -c $< -o $@

$(FBUILD)/fuzz-%: $(FBUILD)/tests/fuzz/%_fuzz.cpp.o $(FBUILD)/tests/fuzz/fuzz.cpp.o $(HARNESS_CXX:%=$(FBUILD)/%.o) $(PORTABLE_CXX:%=$(FBUILD)/%.o)
	$(call say,LINK,$@)
	$(Q)$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $^ $(HLDLIBS)

$(H32BUILD)/%.cpp.o: %.cpp $(ARCH_FILE) | deps
	@mkdir -p $(@D)
	$(call say,CXX32,$<)
	$(Q)$(H32CXX) $(H32CXXFLAGS) -c $< -o $@

$(H32BUILD)/gtest-all.o: | deps
	@mkdir -p $(@D)
	$(call say,CXX32,gtest-all.cc)
	$(Q)$(H32CXX) -std=c++20 -m32 -O2 -isystem $(GTEST_SRC)/include -I$(GTEST_SRC) -c $(GTEST_SRC)/src/gtest-all.cc -o $@

# the P6 build of the same portable code, every symbol p6.NAME (tests/asm/p6_build_test.cpp)
P6_PORTABLE32_BUNDLE := $(H32BUILD)/p6-portable.bundle.o
$(P6_PORTABLE32_BUNDLE): $(patsubst %,$(KBUILD)/p6/%.o,kernel/lib/words.cpp kernel/lib/keys.cpp kernel/lib/fmt.cpp $(CORE_CXX)) $(P6_LOOP_OBJS)
	$(call bundle,$^,-,rename)
$(ASM_TESTS): $(ASM_TEST_CXX:%=$(H32BUILD)/%.o) $(PORTABLE32_OBJS) $(P6_PORTABLE32_BUNDLE) $(H32BUILD)/gtest-all.o
	$(call say,LINK,$@)
	$(Q)$(H32CXX) -static -m32 -Wl,-z,noexecstack -o $@ $^ -lpthread 2>&1 | { grep -v -e getaddrinfo -e MakeConnection || true; }

$(CYCLES): $(CYCLES_CXX:%=$(H32BUILD)/%.o) $(PORTABLE32_OBJS)
	$(call say,LINK,$@)
	$(Q)$(H32CXX) -static -m32 -Wl,-z,noexecstack -o $@ $^

$(NATIVE32): $(H32BUILD)/qemu/tools/native32_main.cpp.o
	$(call say,LINK,$@)
	$(Q)$(H32CXX) -static -m32 -Wl,-z,noexecstack -o $@ $^

$(RUN32): qemu/tools/run32 $(NATIVE32)
	$(Q)cp $< $@

# (the code under test first: shared inline functions are its -O2 copies)
$(TESTS): $(HARNESS_OBJS) $(TEST_CXX:%=$(HBUILD)/%.o)
	$(call say,LINK,$@)
	$(Q)$(HCXX) -o $@ $^ -lgtest $(HLDLIBS)

$(BROWSER_TESTS): $(BROWSER_TEST_CXX:%=$(HBUILD)/%.o) $(HARNESS_OBJS)
	$(call say,LINK,$@)
	$(Q)$(HCXX) -o $@ $^ -lgtest $(HLDLIBS)

# `make usb DEVICE=/dev/sdX [FORCE=1] [YES=1]`: the ISO onto a USB stick, after the checks in
# qemu/tools/write_usb.sh (a removable or USB whole disk, nothing mounted, at most 64 GiB).
usb: $(ISO)
	@DEVICE="$(DEVICE)" FORCE="$(FORCE)" YES="$(YES)" qemu/tools/write_usb.sh $(ISO)

# `make run SCENE=corridor DISPLAY=1`: a window. DISPLAY=1 on make's command line hides X's own
# DISPLAY from the recipe; $(shell) still sees the environment make started with.
X_DISPLAY := $(shell printenv DISPLAY)
# `make run` builds what it runs: the kernel and the harness (not the ISO, the tools or the tests).
RUN_DEPS := $(if $(filter 1,$(DISPLAY)),DISPLAY,RUN)
run:
	@$(if $(filter 1,$(DISPLAY)),$(if $(X_DISPLAY)$(WAYLAND_DISPLAY),,echo "make run DISPLAY=1: no display for a window (neither DISPLAY nor WAYLAND_DISPLAY is set); make run plays headless"; exit 1))
	@$(MAKE) -s DEPS_FOR=$(RUN_DEPS) deps
	@$(MAKE) -s -j$(NPROC) DEPS_FOR=$(RUN_DEPS) $(KERNEL) $(HARNESS)
	DISPLAY=$(X_DISPLAY) $(HARNESS) run --kernel $(KERNEL) --out $(BUILD)/run $(if $(SCENE),--scene $(SCENE)) \
		$(if $(MAPPER),--mapper $(MAPPER)) $(if $(filter 1,$(DISPLAY)),--display)

# `make bench`: every mapper on every demo scene; the report in build/report (docs/bench.md), and,
# when the run is full, the cost model auto chooses by (kernel/mappers/auto/costs.cpp), the errors the
# on-screen bench shows (kernel/mappers/errors.cpp), and the docs' figures (docs/data/trade.csv,
# the generated tables of README.md and docs/results.md, the README's plot).
# SCENES=a,b MAPPERS=x,y FRAMES=N narrow it. The frames run again on the timing model's 486 and
# Pentium (docs/cycles.md, "Whole frames"); TARGET=486 or pentium: that one only; TARGET=icount: none.
# Then the gallery, with the report's speeds.
BENCH_TARGETS = $(if $(filter icount,$(TARGET)),,$(if $(TARGET),$(TARGET),486$(comma)pentium))
comma := ,
bench report:
	@$(MAKE) -s DEPS_FOR=BENCH deps
	@$(MAKE) -s -j$(NPROC) DEPS_FOR=BENCH $(KERNEL) $(BENCH) $(CYCLES) $(RUN32) $(GALLERY) $(TIMING_PLUGIN)
	$(BENCH) --out $(BUILD)/report $(if $(SCENES),--scenes $(SCENES)) $(if $(MAPPERS),--mappers $(MAPPERS)) \
		$(if $(FRAMES),--frames $(FRAMES)) $(if $(BENCH_TARGETS),--targets $(BENCH_TARGETS))
	@$(if $(SCENES)$(MAPPERS)$(FRAMES),echo "not copied (a narrowed run): the cost model and measured errors and the docs' figures in $(BUILD)/report",\
		cmp -s $(BUILD)/report/costs.cpp kernel/mappers/auto/costs.cpp && echo "cost model unchanged" || \
		{ cp $(BUILD)/report/costs.cpp kernel/mappers/auto/costs.cpp && echo "cost model updated: kernel/mappers/auto/costs.cpp (commit it)"; }; \
		cmp -s $(BUILD)/report/errors.cpp kernel/mappers/errors.cpp && echo "measured errors unchanged" || \
		{ cp $(BUILD)/report/errors.cpp kernel/mappers/errors.cpp && echo "measured errors updated: kernel/mappers/errors.cpp (commit it)"; }; \
		cmp -s $(BUILD)/report/trade.csv docs/data/trade.csv || { mkdir -p docs/data && cp $(BUILD)/report/trade.csv docs/data/trade.csv && \
			echo "the docs' figures updated: docs/data/trade.csv (commit it)"; }; \
		$(BENCH) --refresh-docs docs/data/trade.csv; \
		if [ -f $(BUILD)/report/trade-corridor.png ]; then cp $(BUILD)/report/trade-corridor.png docs/img/trade-corridor.png; fi)
	$(GALLERY_RUN)

# `make listing MAPPER=NAME CPU=486|pentium`: a registered mapper's NASM inner loop through the
# timing model, a line an instruction (docs/cycles.md)
listing: $(KERNEL) $(TIMING)
	@test -n "$(MAPPER)" || { echo "usage: make listing MAPPER=NAME [CPU=486|pentium] (a mapper with a NASM loop: docs/cycles.md)"; exit 2; }
	@$(TIMING) --cpu $(or $(CPU),486) --mapper "$(MAPPER)"

# `make profile SCENE=NAME [MAPPER=auto] [AGAINST=fast-oriented-1] [BUDGET=E] [FRAMES=8]`: MAPPER's
# instructions against AGAINST's on the scene's bench frames, by function (docs/bench.md)
profile:
	@test -n "$(SCENE)" || { echo "usage: make profile SCENE=NAME [MAPPER=auto] [AGAINST=fast-oriented-1] [BUDGET=E] [FRAMES=8]"; exit 2; }
	@$(MAKE) -s DEPS_FOR=BENCH deps
	@$(MAKE) -s -j$(NPROC) DEPS_FOR=BENCH $(KERNEL) $(PROFILE) $(PROFILE_PLUGIN)
	$(PROFILE) --scene $(SCENE) $(if $(MAPPER),--mapper $(MAPPER)) $(if $(AGAINST),--against $(AGAINST)) $(if $(BUDGET),--budget $(BUDGET)) $(if $(FRAMES),--frames $(FRAMES))

# `make gallery`: a page a demo scene in build/gallery, every mapper's frame beside its footprint-error
# map, fastest first (speeds from build/report when make bench made one; docs/bench.md, "The gallery").
# SCENES=a,b MAPPERS=x,y narrow it.
GALLERY_RUN = $(GALLERY) --out $(BUILD)/gallery --report $(BUILD)/report $(if $(SCENES),--scenes $(SCENES)) \
	$(if $(MAPPERS),--mappers $(MAPPERS))
gallery:
	@$(MAKE) -s DEPS_FOR=BUILD deps
	@$(MAKE) -s -j$(NPROC) DEPS_FOR=BUILD $(GALLERY) $(FREEDOOM_TEXTURES)
	$(GALLERY_RUN)

# `make test-gallery`: every page of a whole gallery opened in a headless Chromium (Debian's chromium,
# installed for this tier only): every image loads, each page shows what it says.
test-gallery: deps
	$(call install,chromium:chromium)
	@$(MAKE) -s -j$(NPROC) $(GALLERY) $(BROWSER_TESTS) $(FREEDOOM_TEXTURES)
	@tests/run $(BROWSER_TESTS)

# `make bounds`: every mapper's error bound against its measured error on 100000 random polygons
# (make test runs 600 of them) and on every demo scene (docs/bounds.md);
# MAPPERS=a,b: those mappers only.
BOUND_POLYGONS ?= 100000
bounds: deps
	@$(MAKE) -s -j$(NPROC) $(TESTS) $(FREEDOOM_TEXTURES)
	MODEXLAB_BOUND_POLYGONS=$(BOUND_POLYGONS) MODEXLAB_BOUND_MAPPERS=$(MAPPERS) $(TESTS) --gtest_filter='Bounds.*:Envelope.*'

# `make fuzz-protocol`: random and mutated commands and uploads to a booted kernel, a marker
# answered after each (make test sends 300; docs/protocol.md).
PROTOCOL_INPUTS ?= 20000
PROTOCOL_SEED ?= 2026
fuzz-protocol: deps
	@$(MAKE) -s -j$(NPROC) all host fixtures
	MODEXLAB_PROTOCOL_FUZZ=$(PROTOCOL_INPUTS) MODEXLAB_PROTOCOL_SEED=$(PROTOCOL_SEED) $(TESTS) --gtest_filter='ProtocolFuzz.*'

# `make extremes`: every mapper through the classes of extreme input, measured against the exact
# reference; build/report/extremes.md and .csv (docs/accuracy.md, "Stability at the extremes").
# EXTREME_POLYGONS= a random class (default 1000), MAPPERS=a,b, CLASSES=a,b narrow it.
EXTREME_POLYGONS ?= 1000
extremes: deps
	@$(MAKE) -s -j$(NPROC) $(EXTREMES)
	$(EXTREMES) --out $(BUILD)/report --polygons $(EXTREME_POLYGONS) $(if $(MAPPERS),--mappers $(MAPPERS)) $(if $(CLASSES),--classes $(CLASSES))

# `make fuzz`: every mapper over FUZZ_POLYGONS random polygons under ASan and UBSan, reads and
# writes bounds-checked (make test draws a share), then every fuzz target under libFuzzer for
# FUZZ_SECONDS (docs/fuzzing.md). `make fuzz-corpus` adds what it found that reaches
# new code to the committed corpora (make test replays them).
FUZZ_POLYGONS ?= 1000000
FUZZ_SEED ?= 2026
FUZZ_SECONDS ?= 120
FUZZ_DEPS := clang++:clang /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a:libclang-rt-14-dev
fuzz: deps
	$(call install,$(FUZZ_DEPS))
	@$(MAKE) -s -j$(NPROC) $(SAN_TESTS) $(FUZZERS)
	MODEXLAB_FUZZ_POLYGONS=$(FUZZ_POLYGONS) MODEXLAB_FUZZ_SEED=$(FUZZ_SEED) $(SAN_TESTS) --gtest_filter='PolygonFuzz.*'
	tests/fuzz/run $(FUZZ_SECONDS) $(FBUILD) $(FUZZ_TARGETS)

fuzz-corpus: deps
	$(call install,$(FUZZ_DEPS))
	@$(MAKE) -s -j$(NPROC) $(FUZZERS)
	@for t in $(FUZZ_TARGETS); do mkdir -p $(FBUILD)/corpus/$$t; before=$$(ls tests/fuzz/corpus/$$t | wc -l); \
		$(FBUILD)/fuzz-$$t -merge=1 tests/fuzz/corpus/$$t $(FBUILD)/corpus/$$t >$(FBUILD)/logs/merge-$$t.log 2>&1 || \
		{ cat $(FBUILD)/logs/merge-$$t.log; exit 1; }; \
		echo "fuzz-corpus: $$t: $$before -> $$(ls tests/fuzz/corpus/$$t | wc -l) inputs"; done

# `make soak N=20`: the system-test tier N times; which tests changed their result (flaky ones).
N ?= 20
soak: deps
	@$(MAKE) -s -j$(NPROC) all host fixtures
	@tests/soak $(N) $(TESTS)

# The 32-bit tests, the sanitizer tests and the fuzz corpora one after another, and beside them
# (tests/run: the last program) the unit and system tests, most of whose time is QEMU's.
# The CPU tier: the system tests that boot the kernel and draw, again on QEMU's models of the era:
# the 486 (no TSC, no CMOV: the PIT clock and the 486's build) and the Pentium (a P5: TSC, no CMOV),
# each with 64 MiB
CPU_TIER_TESTS := Boot.KernelByMultiboot:Boot.IsoAsCdrom:Cpu.*:Video.EveryPatternInEveryPageMatchesTheHostRendering:$\
	Scenes3d.EveryBuiltInSceneEqualsTheHostAtFixedFrames:Render.KernelPicturesEqualTheHostsForEveryMapperOnEveryScene:$\
	Mappers.TheKernelSelftestComparesEveryNasmLoopWithItsTwin:Bench.FiguresAddUpAndEqualTheHostsCounts:Clock.*
CPU_TIER := $(foreach cpu,486 pentium,MODEXLAB_TEST_CPU=$(cpu),MODEXLAB_TEST_MEMORY_MIB=16@$(TESTS)::$(CPU_TIER_TESTS))

test: deps
	@$(MAKE) -s -j$(NPROC) all host fixtures
	@tests/run $(ASM_TESTS) $(SAN_TESTS) $(FUZZ_REPLAY) $(CPU_TIER) $(TESTS)

# `make test-cpu`: the CPU tier alone (make test runs it too)
test-cpu: deps
	@$(MAKE) -s -j$(NPROC) all host fixtures
	@tests/run $(CPU_TIER)

# `make test-bochs`: the Bochs tier alone (tests/system/bochs_test.cpp; make test runs it too)
test-bochs: deps
	@$(MAKE) -s -j$(NPROC) $(ISO) $(TESTS)
	@GTEST_FILTER='Bochs.*' tests/run $(TESTS)

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
