; CPU-exception entry stubs (vectors 0-31): build an ExceptionFrame and hand it to exception_handler.
; IRQ stubs (vectors 0x20-0x2F, the remapped PICs): save the registers, call irq_handler(irq), return.
; Also the deliberate fault sites the `fault` command jumps into, named so tests can find their addresses.

bits 32

extern exception_handler
extern irq_handler

; Vectors where the CPU pushes an error code: 8, 10-14, 17, 21, 29, 30.
%macro ISR_NOERR 1
isr_stub_%1:
    push dword 0                        ; uniform frame: a zero error code
    push dword %1
    jmp isr_common
%endmacro

%macro ISR_ERR 1
isr_stub_%1:
    push dword %1
    jmp isr_common
%endmacro

section .text

isr_common:
    ; stack: vector, error code, eip, cs, eflags (ring 0 to ring 0: no ss/esp)
    pushad                              ; ExceptionFrame: edi esi ebp esp ebx edx ecx eax, then the above
    cld
    mov ax, 0x10                        ; trust nothing about the data segments at fault time
    mov ds, ax
    mov es, ax
    push esp                            ; exception_handler(const ExceptionFrame*)
    call exception_handler
.stop:                                  ; the handler ends the run; never return into a faulting context
    cli
    hlt
    jmp .stop

ISR_NOERR 0
ISR_NOERR 1
ISR_NOERR 2
ISR_NOERR 3
ISR_NOERR 4
ISR_NOERR 5
ISR_NOERR 6
ISR_NOERR 7
ISR_ERR   8
ISR_NOERR 9
ISR_ERR   10
ISR_ERR   11
ISR_ERR   12
ISR_ERR   13
ISR_ERR   14
ISR_NOERR 15
ISR_NOERR 16
ISR_ERR   17
ISR_NOERR 18
ISR_NOERR 19
ISR_NOERR 20
ISR_ERR   21
ISR_NOERR 22
ISR_NOERR 23
ISR_NOERR 24
ISR_NOERR 25
ISR_NOERR 26
ISR_NOERR 27
ISR_NOERR 28
ISR_ERR   29
ISR_ERR   30
ISR_NOERR 31

; An IRQ interrupts whatever runs (ring 0, flat segments): the general registers saved around the
; C++ handler, which touches no x87 or SSE state; iret restores EFLAGS (the direction flag too).
%macro IRQ 1
irq_stub_%1:
    pushad
    cld
    push dword %1
    call irq_handler
    add esp, 4
    popad
    iretd
%endmacro

%assign i 0
%rep 16
IRQ i
%assign i i+1
%endrep

section .rodata
global irq_stub_table
irq_stub_table:
%assign i 0
%rep 16
    dd irq_stub_%+i
%assign i i+1
%endrep

global isr_stub_table
isr_stub_table:
%assign i 0
%rep 32
    dd isr_stub_%+i
%assign i i+1
%endrep

section .text
; Deliberate faults. Each label is the address of the faulting instruction, as EIP will report it.
global fault_ud2, fault_divide, fault_gp
fault_ud2:
    ud2                                 ; #UD, vector 6
fault_divide:
    xor edx, edx
    xor eax, eax
    xor ecx, ecx
.site:
    div ecx                             ; #DE, vector 0
global fault_divide_site
fault_divide_site equ fault_divide.site
fault_gp:
    mov ax, 0x18                        ; beyond the GDT's limit: #GP, vector 13, error code 0x18
.site:
    mov ds, ax
global fault_gp_site
fault_gp_site equ fault_gp.site

; A triple fault: with an empty IDT, int3 raises #GP, which raises #DF, which shuts the CPU down.
; Under QEMU -no-reboot that ends QEMU with status 0: the harness must count it as a failure.
global fault_triple
fault_triple:
    lidt [empty_idtr]
    int3

; A hang: interrupts off, halted for good. The harness must notice the silence and kill QEMU.
global fault_hang
fault_hang:
    cli
.halt:
    hlt
    jmp .halt

section .rodata
empty_idtr:
    dw 0
    dd 0
