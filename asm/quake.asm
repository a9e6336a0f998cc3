; quake_span_loop_asm: Quake's span drawer with the x87 divide for the next segment's end started before
; the current segment's pixels are drawn (d_draw16.s overlaps it with the pixels too, starting it
; after 8 of the 16), the integer loop stepping one texel pointer with a two-entry advance table
; (sbb/adc). Twin of quake_span_loop in kernel/mappers/quake.cpp,
; whose arithmetic (d_scan.c's C) it follows operation for operation: the x87 runs at 53-bit
; precision and rounds to nearest, and only the float-to-int conversions chop.
;
; FPU stack between segments: st0 = 1/z, st1 = t/z, st2 = s/z (and z on top while a divide runs).
; Integer loop: esi texel pointer, edi destination, ebx s fraction (bits 31..16), edx t fraction,
; ebp s fraction step, ecx 0 / -1 (t carried), al texel.

bits 32

%include "quake.inc"
%include "loop.inc"

section .rodata
align 8
c65536:     dq 65536.0

; locals, esp-relative
L_ARGS      equ 0       ; the argument block
L_COUNT     equ 4       ; pixels after the segment being set up
L_SPAN      equ 8       ; that segment's length
L_LAST      equ 12      ; 1 when it is the span's last segment
L_S         equ 16      ; s, t at the current segment's start (16.16)
L_T         equ 20
L_SNEXT     equ 24      ; s, t at its end
L_TNEXT     equ 28
L_SSTEP     equ 32
L_TSTEP     equ 36
L_TABLE     equ 40      ; [40] t carried, [44] t did not carry
L_TFSTEP    equ 48      ; t fraction step (bits 31..16)
L_TMP       equ 52
L_CW        equ 56      ; the caller's control word (round to nearest)
L_CWCHOP    equ 58      ; the same, chopping
L_N         equ 60      ; segment length
L_PIX       equ 64      ; pixels left in the integer loop
L_STARTED   equ 68      ; 1 when the next segment's divide is running
L_FRAC_T    equ 72      ; t fraction, saved while the next segment is set up
LOCALS      equ 76

section .text

; st0 (popped) -> eax, truncated toward zero (FISTP in chop mode: 0x80000000 when out of range)
%macro CHOP 0
    fldcw [esp + L_CWCHOP]
    fistp dword [esp + L_TMP]
    fldcw [esp + L_CW]
    mov eax, [esp + L_TMP]
%endmacro

; eax = min(max(eax, %2), %3) with the high bound tested first, as the C does; %1 a label prefix
%macro CLAMP 3
    cmp eax, %3
    jle %1_not_high
    mov eax, %3
    jmp %1_done
%1_not_high:
    cmp eax, %2
    jge %1_done
    mov eax, %2
%1_done:
%endmacro

; Sets up the next segment from L_COUNT: its length and whether it is the last; advances s/z, t/z,
; 1/z to its end and starts the divide for z there. FPU: (zi, tdivz, sdivz) -> (z, zi, tdivz, sdivz).
%macro SEGMENT_START 1
    mov eax, [esp + L_ARGS]
    mov ecx, [esp + L_COUNT]
    mov edx, [esp + L_N]
    cmp ecx, edx
    jle %1_short
    mov ecx, edx
%1_short:
    mov [esp + L_SPAN], ecx
    sub [esp + L_COUNT], ecx
    jz %1_last
    mov dword [esp + L_LAST], 0
    fld qword [eax + QUAKE_s_stepu_n]
    faddp st3, st0                      ; sdivz += sdivz16stepu
    fld qword [eax + QUAKE_t_stepu_n]
    faddp st2, st0                      ; tdivz += tdivz16stepu
    fld qword [eax + QUAKE_z_stepu_n]
    faddp st1, st0                      ; zi += zi16stepu
    jmp %1_divide
%1_last:
    mov dword [esp + L_LAST], 1
    dec ecx
    mov [esp + L_TMP], ecx
    fild dword [esp + L_TMP]            ; spancountminus1
    fld st0
    fmul qword [eax + QUAKE_s_stepu]
    faddp st4, st0                      ; sdivz += d_sdivzstepu * spancountminus1
    fld st0
    fmul qword [eax + QUAKE_t_stepu]
    faddp st3, st0
    fmul qword [eax + QUAKE_z_stepu]
    faddp st1, st0                      ; zi += d_zistepu * spancountminus1
%1_divide:
    fld qword [c65536]
    fdiv st0, st1                       ; z = 65536 / zi: in flight from here
%endmacro

; Collects the divide: snext, tnext (clamped to [N, bbextent]) and the steps from L_S, L_T.
; FPU: (z, zi, tdivz, sdivz) -> (zi, tdivz, sdivz).
%macro SEGMENT_FINISH 1
    fld st0
    fmul st0, st4                       ; sdivz * z
    CHOP
    mov ecx, [esp + L_ARGS]
    add eax, [ecx + QUAKE_sadjust_16_16]
    CLAMP %1_s, [esp + L_N], [ecx + QUAKE_bbextents]
    mov [esp + L_SNEXT], eax
    fmul st0, st2                       ; tdivz * z
    CHOP
    mov ecx, [esp + L_ARGS]
    add eax, [ecx + QUAKE_tadjust_16_16]
    CLAMP %1_t, [esp + L_N], [ecx + QUAKE_bbextentt]
    mov [esp + L_TNEXT], eax
    cmp dword [esp + L_LAST], 0
    jne %1_last_steps
    mov ecx, [esp + L_ARGS]
    mov ecx, [ecx + QUAKE_shift]
    mov eax, [esp + L_SNEXT]
    sub eax, [esp + L_S]
    sar eax, cl                         ; (snext - s) >> 4
    mov [esp + L_SSTEP], eax
    mov eax, [esp + L_TNEXT]
    sub eax, [esp + L_T]
    sar eax, cl
    mov [esp + L_TSTEP], eax
    jmp %1_done
%1_last_steps:
    mov ecx, [esp + L_SPAN]
    dec ecx
    jz %1_done                          ; one pixel: the steps are never used
    mov eax, [esp + L_SNEXT]
    sub eax, [esp + L_S]
    cdq
    idiv ecx                            ; (snext - s) / (spancount - 1), truncating
    mov [esp + L_SSTEP], eax
    mov eax, [esp + L_TNEXT]
    sub eax, [esp + L_T]
    cdq
    idiv ecx
    mov [esp + L_TSTEP], eax
%1_done:
%endmacro

global quake_span_loop_asm
quake_span_loop_asm:
    LOOP_ENTER LOCALS
    mov eax, LOOP_ARG(LOCALS)
    mov [esp + L_ARGS], eax
    fnstcw [esp + L_CW]
    mov cx, [esp + L_CW]
    or cx, 0x0C00                       ; rounding control: chop
    mov [esp + L_CWCHOP], cx
    mov ecx, [eax + QUAKE_shift]
    mov edx, 1
    shl edx, cl
    mov [esp + L_N], edx
    mov ecx, [eax + QUAKE_count]
    mov [esp + L_COUNT], ecx
    mov dword [esp + L_SSTEP], 0
    mov dword [esp + L_TSTEP], 0
    mov edi, [eax + QUAKE_dst]

    ; s/z, t/z, 1/z at the first pixel: (origin + dv * stepv) + du * stepu
    fild dword [eax + QUAKE_y]
    fmul qword [eax + QUAKE_s_stepv]
    fadd qword [eax + QUAKE_s_origin]
    fild dword [eax + QUAKE_x]
    fmul qword [eax + QUAKE_s_stepu]
    faddp st1, st0
    fild dword [eax + QUAKE_y]
    fmul qword [eax + QUAKE_t_stepv]
    fadd qword [eax + QUAKE_t_origin]
    fild dword [eax + QUAKE_x]
    fmul qword [eax + QUAKE_t_stepu]
    faddp st1, st0
    fild dword [eax + QUAKE_y]
    fmul qword [eax + QUAKE_z_stepv]
    fadd qword [eax + QUAKE_z_origin]
    fild dword [eax + QUAKE_x]
    fmul qword [eax + QUAKE_z_stepu]
    faddp st1, st0                      ; st0 = zi, st1 = tdivz, st2 = sdivz
    fld qword [c65536]
    fdiv st0, st1                       ; the span's first divide: nothing to overlap it with
    fld st0
    fmul st0, st4
    CHOP
    mov ecx, [esp + L_ARGS]
    add eax, [ecx + QUAKE_sadjust_16_16]
    CLAMP .s0, 0, [ecx + QUAKE_bbextents]
    mov [esp + L_S], eax
    fmul st0, st2
    CHOP
    mov ecx, [esp + L_ARGS]
    add eax, [ecx + QUAKE_tadjust_16_16]
    CLAMP .t0, 0, [ecx + QUAKE_bbextentt]
    mov [esp + L_T], eax

    ; the first segment's end: computed now, since its pixels need it
    SEGMENT_START .first_start
    SEGMENT_FINISH .first_finish

.segment:
    ; the integer loop's registers for this segment, from s, t and the steps
    mov eax, [esp + L_SPAN]
    mov [esp + L_PIX], eax
    mov ecx, [esp + L_ARGS]
    mov eax, [esp + L_T]
    sar eax, 16
    imul eax, [ecx + QUAKE_pitch]
    mov esi, [esp + L_S]
    sar esi, 16
    add esi, eax
    add esi, [ecx + QUAKE_texels]       ; esi = texels + (s >> 16) + (t >> 16) * pitch
    mov eax, [esp + L_TSTEP]
    sar eax, 16
    imul eax, [ecx + QUAKE_pitch]
    mov edx, [esp + L_SSTEP]
    sar edx, 16
    add eax, edx
    mov [esp + L_TABLE + 4], eax        ; whole s step + whole t step * pitch
    add eax, [ecx + QUAKE_pitch]
    mov [esp + L_TABLE], eax            ; and one row more when t's fraction carries
    mov eax, [esp + L_TSTEP]
    shl eax, 16
    mov [esp + L_TFSTEP], eax
    mov ebp, [esp + L_SSTEP]
    shl ebp, 16
    mov ebx, [esp + L_S]
    shl ebx, 16
    mov edx, [esp + L_T]
    shl edx, 16

    ; start the divide for the next segment's end, then draw this one under it
    mov dword [esp + L_STARTED], 0
    cmp dword [esp + L_COUNT], 0
    je .pixel
    mov [esp + L_FRAC_T], edx           ; SEGMENT_START uses eax, ecx and edx
    SEGMENT_START .next_start
    mov edx, [esp + L_FRAC_T]
    mov dword [esp + L_STARTED], 1
.pixel:
    mov al, [esi]
    mov [edi], al
    inc edi
    add edx, [esp + L_TFSTEP]           ; t fraction; CF = t carry
    sbb ecx, ecx                        ; 0, or -1 when t carried
    add ebx, ebp                        ; s fraction; CF = s carry
    adc esi, [esp + L_TABLE + 4 + ecx * 4]
    dec dword [esp + L_PIX]
    jnz .pixel

    ; s = snext, t = tnext; collect the running divide for the next segment
    mov eax, [esp + L_SNEXT]
    mov [esp + L_S], eax
    mov eax, [esp + L_TNEXT]
    mov [esp + L_T], eax
    cmp dword [esp + L_STARTED], 0
    je .done
    SEGMENT_FINISH .next_finish
    jmp .segment

.done:
    fstp st0
    fstp st0
    fstp st0
    LOOP_LEAVE LOCALS
