; fast_subdiv_loop_asm (fast-subdiv-N): one row span, segment by segment; twin of
; kernel/mappers/fastsubdiv.cpp (fast_subdiv_loop), which it matches bit for bit. Each exact point
; in x87 as the twin computes it (53-bit precision, the same operations in the same order, the
; 64-bit conversion rounding to nearest), the steps between two points by their 32-bit difference,
; the pixels by the 8:16 core (asm/core816.inc) in pairs, entered part-way as fast_run_loop_asm
; enters it.

bits 32

%include "fastsubdiv.inc"
%include "loop.inc"
%include "core816.inc"

section .rodata
align 8
subpixel_one: dq 256.0                  ; SUBPIXEL_ONE: a pixel in subpixels
scale_16_16:  dq 65536.0

L_ARGS   equ 0
L_K      equ 4                          ; the segment's first pixel
L_END    equ 8                          ; its next exact point
L_LEN    equ 12                         ; its pixels
L_D      equ 16                         ; the pixels between its exact points (the last segment's divisor)
L_DST    equ 20                         ; its first pixel's address
L_U0     equ 24                         ; 16.16 at its first pixel
L_V0     equ 28
L_U1     equ 32                         ; qword: 16.16 at its next exact point (the low dword kept)
L_V1     equ 40                         ; qword
L_DU     equ 48                         ; its steps
L_DV     equ 52
L_ODD    equ 56                         ; 1: an odd last pixel after the pairs
L_ENTRY  equ 60
L_FRAME  equ 64

section .text

; the exact point at pixel [esp + %1] into [esp + L_U1], [esp + L_V1]; ecx: the block
%macro POINT 1
    fild dword [esp + %1]
    fmul qword [subpixel_one]
    fadd qword [ecx + FSUB_x]           ; x = x0 + k * 256
    fld qword [ecx + FSUB_g]
    fmul st0, st1
    fadd qword [ecx + FSUB_c]           ; q = c0 + g0 x
    fld qword [ecx + FSUB_g + 8]
    fmul st0, st2
    fadd qword [ecx + FSUB_c + 8]       ; pu
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + L_U1]            ; u in 16.16, nearest
    fld qword [ecx + FSUB_g + 16]
    fmul st0, st2
    fadd qword [ecx + FSUB_c + 16]      ; pv
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + L_V1]
    fstp st0                            ; q
    fstp st0                            ; x
%endmacro

global fast_subdiv_loop_asm
fast_subdiv_loop_asm:
    LOOP_ENTER L_FRAME
    mov ecx, LOOP_ARG(L_FRAME)
    cmp dword [ecx + FSUB_count], 0
    jle .done
    mov [esp + L_ARGS], ecx
    mov eax, [ecx + FSUB_dst]
    mov [esp + L_DST], eax
    mov dword [esp + L_K], 0
    POINT L_K
    mov eax, [esp + L_U1]
    mov [esp + L_U0], eax
    mov eax, [esp + L_V1]
    mov [esp + L_V0], eax
.segment:
    mov ecx, [esp + L_ARGS]
    mov esi, ecx
    mov ecx, [esi + FSUB_shift]
    mov ebx, 1
    shl ebx, cl                         ; n
    mov eax, [esi + FSUB_count]
    sub eax, [esp + L_K]                ; pixels left
    cmp eax, ebx
    jle .last_segment
    mov [esp + L_LEN], ebx              ; n pixels, to the exact point n on
    add ebx, [esp + L_K]
    mov [esp + L_END], ebx
    mov ecx, esi
    POINT L_END
    mov ecx, [esi + FSUB_shift]
    mov eax, [esp + L_U1]
    sub eax, [esp + L_U0]
    sar eax, cl                         ; du
    mov edx, [esp + L_V1]
    sub edx, [esp + L_V0]
    sar edx, cl                         ; dv
    jmp .draw
.last_segment:                          ; the pixels left, to the exact point at the last
    mov [esp + L_LEN], eax
    dec eax
    jz .one_pixel
    mov [esp + L_D], eax
    mov ebx, [esi + FSUB_count]
    dec ebx
    mov [esp + L_END], ebx
    mov ecx, esi
    POINT L_END
    mov eax, [esp + L_U1]
    sub eax, [esp + L_U0]
    cdq
    idiv dword [esp + L_D]
    mov ebx, eax                        ; du
    mov eax, [esp + L_V1]
    sub eax, [esp + L_V0]
    cdq
    idiv dword [esp + L_D]
    mov edx, eax                        ; dv
    mov eax, ebx
    jmp .draw
.one_pixel:
    xor eax, eax
    xor edx, edx
.draw:                                  ; eax: du, edx: dv
    mov [esp + L_DU], eax
    mov [esp + L_DV], edx
    mov ecx, [esp + L_LEN]
    mov eax, ecx
    and eax, 1
    mov [esp + L_ODD], eax
    shr ecx, 1                          ; pairs
    mov edi, [esp + L_DST]
    PAIR_ENTRY edi, edx, entries        ; blocks, the first one partial
    mov esi, [esp + L_DU]
    shl esi, 16                         ; du fraction
    mov ebp, [esp + L_DV]
    shl ebp, 16                         ; dv fraction
    mov ebx, [esp + L_ARGS]
    mov ebx, [ebx + FSUB_texture]
    mov bl, [esp + L_U0 + 2]            ; u whole
    mov bh, [esp + L_V0 + 2]            ; v whole
    mov edx, [esp + L_V0]
    shl edx, 16                         ; v fraction
    mov dl, [esp + L_DU + 2]            ; du whole
    mov dh, [esp + L_DV + 2]            ; dv whole
    mov eax, [esp + L_U0]
    shl eax, 16                         ; u fraction
    test ecx, ecx
    jz .odd_pixel                       ; no pair: one pixel
    PAIRS_AND_ODD .next
.next:
    mov eax, [esp + L_LEN]
    add [esp + L_DST], eax
    add eax, [esp + L_K]
    mov [esp + L_K], eax
    mov ecx, [esp + L_ARGS]
    cmp eax, [ecx + FSUB_count]
    jge .done
    mov eax, [esp + L_U1]
    mov [esp + L_U0], eax
    mov eax, [esp + L_V1]
    mov [esp + L_V0], eax
    jmp .segment
.done:
    LOOP_LEAVE L_FRAME

section .rodata
align 4
entries:
    dd fast_subdiv_loop_asm.e0, fast_subdiv_loop_asm.e1, fast_subdiv_loop_asm.e2, fast_subdiv_loop_asm.e3
    dd fast_subdiv_loop_asm.e4, fast_subdiv_loop_asm.e5, fast_subdiv_loop_asm.e6, fast_subdiv_loop_asm.e7
