; Multiboot v1 header and the 32-bit entry: own GDT, stack, zeroed .bss, FPU, C++ constructors, kernel_main.

bits 32

MB_MAGIC        equ 0x1BADB002
MB_FLAG_ALIGN   equ 1 << 0              ; modules page-aligned
MB_FLAG_MEMINFO equ 1 << 1              ; mem_lower/mem_upper and the memory map
MB_FLAG_VIDEO   equ 1 << 2              ; the video fields below: a UEFI loader hands over its framebuffer
MB_FLAGS        equ MB_FLAG_ALIGN | MB_FLAG_MEMINFO | MB_FLAG_VIDEO

KERNEL_CS       equ 0x08
KERNEL_DS       equ 0x10
STACK_BYTES     equ 256 * 1024      ; fatmap-lut keeps its 64 KiB table on the stack

section .multiboot progbits alloc noexec nowrite align=4
    dd MB_MAGIC
    dd MB_FLAGS
    dd -(MB_MAGIC + MB_FLAGS)
    dd 0, 0, 0, 0, 0                    ; header, load, load end, bss end, entry: unused (the ELF's own)
    dd 0                                ; mode type: linear graphics (GRUB's gfxpayload decides: text under BIOS)
    dd 0, 0, 32                         ; width, height: no preference; 32 bits a pixel

section .rodata
align 8
; Flat 4 GiB ring-0 segments; a loader's GDT may live in memory we are about to reuse.
gdt:
    dq 0                                ; 0x00 null
    dq 0x00CF9A000000FFFF               ; 0x08 code: base 0, limit 4 GiB, 32-bit, execute/read
    dq 0x00CF92000000FFFF               ; 0x10 data: base 0, limit 4 GiB, 32-bit, read/write
gdt_end:
gdt_descriptor:
    dw gdt_end - gdt - 1
    dd gdt
; x87 control word: all exceptions masked, precision control 10b (53-bit), round to nearest
fpu_control:
    dw 0x027F

section .bss
align 16
stack_bottom:
    resb STACK_BYTES
stack_top:
fpu_status:     resw 1                  ; (word-aligned: stack_top is)
global fpu_present
fpu_present:    resb 1                  ; 1 where the probe found an FPU

section .text
global _start
extern kernel_start
extern __bss_start, __bss_end
extern __init_array_start, __init_array_end

_start:
    ; eax = multiboot magic, ebx = info pointer; keep them in edx and ebx until the call
    cli
    cld
    mov edx, eax
    lgdt [gdt_descriptor]
    jmp KERNEL_CS:.reload_cs
.reload_cs:
    mov ax, KERNEL_DS
    mov ds, ax
    mov es, ax
    mov fs, ax
    mov gs, ax
    mov ss, ax

    ; zero .bss (the stack lives there, so nothing may be pushed yet); the linker aligns both ends to 4
    mov edi, __bss_start
    mov ecx, __bss_end
    sub ecx, edi
    shr ecx, 2
    xor eax, eax
    rep stosd

    mov esp, stack_top
    xor ebp, ebp                        ; ends frame-pointer walks
    push edx                            ; the constructors may clobber caller-saved registers
    push ebx

    ; x87: CR0.EM off (no emulation), MP and NE on (native #MF reporting), then a clean FPU state
    ; with 53-bit precision: double arithmetic then rounds exactly as the host's SSE2 does. Whether
    ; there is an FPU: FNINIT and FNSTSW (no-wait forms, safe without one) leave a status of 0 only
    ; where there is one (fpu_present: kernel_start refuses a PC without)
    mov eax, cr0
    and eax, ~(1 << 2)
    or eax, (1 << 1) | (1 << 5)
    mov cr0, eax
    fninit
    mov word [fpu_status], 0x5A5A
    fnstsw [fpu_status]
    cmp word [fpu_status], 0
    jne .no_fpu
    fldcw [fpu_control]
    mov byte [fpu_present], 1
.no_fpu:

    ; the C++ built once's global constructors, in link order (kernel_start runs the others)
    mov esi, __init_array_start
.ctor_loop:
    cmp esi, __init_array_end
    jae .ctors_done
    call [esi]
    add esi, 4
    jmp .ctor_loop
.ctors_done:

    pop ebx
    pop edx
    push ebx                            ; kernel_start(uint32_t magic, const MultibootInfo* info)
    push edx
    call kernel_start

.halt:                                  ; kernel_start does not return; if it does, stop here for good
    cli
    hlt
    jmp .halt
