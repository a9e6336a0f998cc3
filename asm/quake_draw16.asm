; quake_draw16_loop_asm: WinQuake's d_draw16.s (D_DrawSpans16) for one span, its instruction
; sequence kept: the 16-pixel segment written out with the FDIV for the next segment's end started
; after its eighth pixel, the last segment entered part way into the written-out pixels through a
; table by its length, its steps by a reciprocal table. Under Quake's single_cw (the caller's control
; word with 24-bit precision and chop, as Sys_SetFPCW makes it and R_RenderView installs it), set at
; entry and the caller's restored at exit. Twin of quake_draw16_loop in kernel/mappers/quake_draw16.cpp.
;
; FPU stack between segments: st0 = 1/z, st1 = t/z, st2 = s/z (and z on top while the divide runs).
; Pixels: esi texel pointer, edi destination, ebx s fraction (16.16 << 16, or 12 bits more on a full
; segment), edx t fraction, ebp s fraction step, [L_TSTEP] t fraction step, ecx 0 / -1 (t carried),
; al texel. Quake's globals are frame slots here.
;
; precision: 24

bits 32

%include "quake_draw16.inc"
%include "loop.inc"

section .rodata
align 4
fp_16:      dd 16.0
fp_64k:     dd 65536.0
; 1/m in 0.31 form, floored, m = 2..15: the last segment's steps are the high dword of 2 delta times it
reciprocal_16:
    dd 0x40000000, 0x2aaaaaaa, 0x20000000, 0x19999999, 0x15555555, 0x12492492, 0x10000000
    dd 0x0e38e38e, 0x0ccccccc, 0x0ba2e8ba, 0x0aaaaaaa, 0x09d89d89, 0x09249249, 0x08888888
; the last segment's entry by its steps m (m + 1 pixels): .e0 draws its one pixel
    ENTRIES entryvec_16, quake_draw16_loop_asm, 16

; the frame, esp-relative: the block's fields Quake reads as globals, then Quake's own variables
L_SDIVZSTEPU    equ 0
L_TDIVZSTEPU    equ 4
L_ZISTEPU       equ 8
L_SDIVZSTEPV    equ 12
L_TDIVZSTEPV    equ 16
L_ZISTEPV       equ 20
L_SDIVZORIGIN   equ 24
L_TDIVZORIGIN   equ 28
L_ZIORIGIN      equ 32
L_SADJUST       equ 36
L_TADJUST       equ 40
L_BBEXTENTS     equ 44
L_BBEXTENTT     equ 48
L_PBASE         equ 52
L_CACHEWIDTH    equ 56
L_U             equ 60
L_V             equ 64
L_COUNT         equ 68
L_DST           equ 72
L_SDIVZ16       equ 76      ; the steps times 16
L_TDIVZ16       equ 80
L_ZI16          equ 84
L_S             equ 88      ; s, t at the segment's start (16.16)
L_T             equ 92
L_SNEXT         equ 96      ; and at its end
L_TNEXT         equ 100
L_SFRACF        equ 104     ; the fractions between segments
L_TFRACF        equ 108
L_ADVANCE       equ 112     ; [112] t carried, [116] t did not carry
L_TSTEP         equ 120     ; t fraction step
L_COUNTTEMP     equ 124     ; pixels after this segment
L_JUMPTEMP      equ 128     ; the last segment's entry
L_SCM1          equ 132     ; spancountminus1
L_CW            equ 136     ; the caller's control word
L_SINGLE_CW     equ 138     ; Quake's
LOCALS          equ 140

; the pixel stepping: t fraction, its carry into ecx, s fraction, the pointer by the advance table
%define ADVANCE [esp + L_ADVANCE + 4 + ecx * 4]

; a written-out pixel: stores the texel loaded by the one before at [edi + %1], loads the next, steps
%macro PIXEL 1
    add edx, [esp + L_TSTEP]
    sbb ecx, ecx
    mov [edi + %1], al
    add ebx, ebp
    mov al, [esi]
    adc esi, ADVANCE
%endmacro

; z (st0) times s/z and t/z into [%1] and [%2] by FISTP (chop): (z, 1/z, t/z, s/z) -> (1/z, t/z, s/z)
%macro S_AND_T 2
    fld st0
    fmul st0, st4
    fxch st1
    fmul st0, st3
    fxch st1
    fistp dword [esp + %1]
    fistp dword [esp + %2]
%endmacro

; s/z, t/z, 1/z to the next full segment's end and its divide started: (1/z, t/z, s/z) -> (z, ...)
%macro SETUP_NOT_LAST 0
    fadd dword [esp + L_ZI16]
    fxch st2
    fadd dword [esp + L_SDIVZ16]
    fxch st2
    fld dword [esp + L_TDIVZ16]
    faddp st2, st0
    fld dword [fp_64k]
    fdiv st0, st1                       ; z = 65536 / (1/z): the divide the pixels overlap
%endmacro

section .text

global quake_draw16_loop_asm
quake_draw16_loop_asm:
    LOOP_ENTER LOCALS
    mov ecx, LOOP_ARG(LOCALS)
    FRAME_COPY ecx, QD16_s_stepu, L_SDIVZSTEPU, QD16_t_stepu, L_TDIVZSTEPU, QD16_z_stepu, L_ZISTEPU, QD16_s_stepv, L_SDIVZSTEPV, QD16_t_stepv, L_TDIVZSTEPV, QD16_z_stepv, L_ZISTEPV
    FRAME_COPY ecx, QD16_s_origin, L_SDIVZORIGIN, QD16_t_origin, L_TDIVZORIGIN, QD16_z_origin, L_ZIORIGIN, QD16_sadjust_16_16, L_SADJUST, QD16_tadjust_16_16, L_TADJUST
    FRAME_COPY ecx, QD16_bbextents, L_BBEXTENTS, QD16_bbextentt, L_BBEXTENTT, QD16_texels, L_PBASE, QD16_pitch, L_CACHEWIDTH, QD16_x, L_U, QD16_y, L_V
    FRAME_COPY ecx, QD16_count, L_COUNT, QD16_dst, L_DST
    fnstcw [esp + L_CW]
    mov ax, [esp + L_CW]
    and ah, 0xF0
    or ah, 0x0C                         ; precision 24 bits, rounding chop: Quake's single_cw
    mov [esp + L_SINGLE_CW], ax
    fldcw [esp + L_SINGLE_CW]

    ; the 16-pixel steps (Quake sets them up once a call of D_DrawSpans16)
    fld dword [esp + L_SDIVZSTEPU]
    fmul dword [fp_16]
    fld dword [esp + L_TDIVZSTEPU]
    fmul dword [fp_16]
    fld dword [esp + L_ZISTEPU]
    fmul dword [fp_16]
    fstp dword [esp + L_ZI16]
    fstp dword [esp + L_TDIVZ16]
    fstp dword [esp + L_SDIVZ16]

    ; s/z, t/z and 1/z at the span's first pixel
    fild dword [esp + L_V]
    fild dword [esp + L_U]              ; du | dv
    fld st1                             ; dv | du | dv
    fmul dword [esp + L_SDIVZSTEPV]     ; dv*sv | du | dv
    fld st1
    fmul dword [esp + L_SDIVZSTEPU]     ; du*su | dv*sv | du | dv
    fld st2
    fmul dword [esp + L_TDIVZSTEPU]     ; du*tu | du*su | dv*sv | du | dv
    fxch st1
    faddp st2, st0                      ; du*tu | du*su + dv*sv | du | dv
    fxch st1
    fld st3
    fmul dword [esp + L_TDIVZSTEPV]     ; dv*tv | du*su + dv*sv | du*tu | du | dv
    fxch st1
    fadd dword [esp + L_SDIVZORIGIN]    ; s/z | dv*tv | du*tu | du | dv
    fxch st4
    fmul dword [esp + L_ZISTEPV]        ; dv*zv | dv*tv | du*tu | du | s/z
    fxch st1
    faddp st2, st0                      ; dv*zv | dv*tv + du*tu | du | s/z
    fxch st2
    fmul dword [esp + L_ZISTEPU]        ; du*zu | dv*tv + du*tu | dv*zv | s/z
    fxch st1
    fadd dword [esp + L_TDIVZORIGIN]    ; t/z | du*zu | dv*zv | s/z
    fxch st2
    faddp st1, st0                      ; dv*zv + du*zu | t/z | s/z
    fld dword [fp_64k]
    fxch st1
    fadd dword [esp + L_ZIORIGIN]       ; 1/z | 64k | t/z | s/z
    fdiv st1, st0                       ; 1/z | z | t/z | s/z

    mov edi, [esp + L_DST]
    mov edx, [esp + L_TADJUST]
    mov esi, [esp + L_SADJUST]
    mov ecx, [esp + L_COUNT]

    ; s and t at the first pixel, and the divide for the first segment's end started
    cmp ecx, 16
    ja .setup_not_last1
    dec ecx
    jz .cleanup1                        ; one pixel: no divide
    mov [esp + L_SCM1], ecx
    fxch st1                            ; z | 1/z | t/z | s/z
    S_AND_T L_S, L_T
    fild dword [esp + L_SCM1]
    fld dword [esp + L_TDIVZSTEPU]
    fld dword [esp + L_ZISTEPU]
    fmul st0, st2                       ; zu*scm1 | tu | scm1
    fxch st1
    fmul st0, st2                       ; tu*scm1 | zu*scm1 | scm1
    fxch st2
    fmul dword [esp + L_SDIVZSTEPU]     ; su*scm1 | zu*scm1 | tu*scm1
    fxch st1
    faddp st3, st0
    fxch st1
    faddp st3, st0
    faddp st3, st0                      ; 1/z | t/z | s/z at the span's last pixel
    fld dword [fp_64k]
    fdiv st0, st1
    jmp .fdiv_in_flight1

.cleanup1:
    fxch st1
    S_AND_T L_S, L_T
    jmp .fdiv_in_flight1

align 4
.setup_not_last1:
    fxch st1
    S_AND_T L_S, L_T
    SETUP_NOT_LAST
.fdiv_in_flight1:
    add esi, [esp + L_S]
    add edx, [esp + L_T]
    mov ebx, [esp + L_BBEXTENTS]
    mov ebp, [esp + L_BBEXTENTT]
    cmp esi, ebx
    ja .clamp_high_or_low0
.clamp_reentry0:
    mov [esp + L_S], esi
    mov ebx, [esp + L_PBASE]
    shl esi, 16
    cmp edx, ebp
    mov [esp + L_SFRACF], esi
    ja .clamp_high_or_low1
.clamp_reentry1:
    mov [esp + L_T], edx
    mov esi, [esp + L_S]
    shl edx, 16
    mov eax, [esp + L_T]
    sar esi, 16
    mov [esp + L_TFRACF], edx
    sar eax, 16
    mov edx, [esp + L_CACHEWIDTH]
    imul eax, edx
    add esi, ebx
    add esi, eax                        ; pbase + (s >> 16) + (t >> 16) * cachewidth
    cmp ecx, 16
    jna .last_segment

    ; a full segment: its end from the divide in flight, its steps exactly delta / 16
.not_last_segment:
    S_AND_T L_SNEXT, L_TNEXT
    mov eax, [esp + L_SNEXT]
    mov edx, [esp + L_TNEXT]
    mov bl, [esi]                       ; the segment's first texel
    sub ecx, 16
    mov ebp, [esp + L_SADJUST]
    mov [esp + L_COUNTTEMP], ecx
    mov ecx, [esp + L_TADJUST]
    mov [edi], bl
    add ebp, eax
    add ecx, edx
    mov eax, [esp + L_BBEXTENTS]
    mov edx, [esp + L_BBEXTENTT]
    cmp ebp, 4096
    jl .clamp_low2
    cmp ebp, eax
    ja .clamp_high2
.clamp_reentry2:
    cmp ecx, 4096
    jl .clamp_low3
    cmp ecx, edx
    ja .clamp_high3
.clamp_reentry3:
    mov [esp + L_SNEXT], ebp
    mov [esp + L_TNEXT], ecx
    sub ebp, [esp + L_S]
    sub ecx, [esp + L_T]
    mov eax, ecx
    mov edx, ebp
    sar eax, 20                         ; whole t step
    jz .zero
    sar edx, 20                         ; whole s step
    mov ebx, [esp + L_CACHEWIDTH]
    imul eax, ebx
    jmp .set_up1
.zero:
    sar edx, 20
    mov ebx, [esp + L_CACHEWIDTH]
.set_up1:
    add eax, edx
    mov edx, [esp + L_TFRACF]
    mov [esp + L_ADVANCE + 4], eax      ; no t carry
    add eax, ebx
    shl ebp, 12                         ; the s step's fraction, 20 bits of it
    mov ebx, [esp + L_SFRACF]
    shl ecx, 12
    mov [esp + L_ADVANCE], eax          ; t carried
    mov [esp + L_TSTEP], ecx
    add edx, ecx
    sbb ecx, ecx
    add ebx, ebp
    adc esi, ADVANCE

    add edx, [esp + L_TSTEP]
    sbb ecx, ecx
    mov al, [esi]
    add ebx, ebp
    mov [edi + 1], al
    adc esi, ADVANCE

    add edx, [esp + L_TSTEP]
    sbb ecx, ecx
    add ebx, ebp
    mov al, [esi]
    adc esi, ADVANCE
%assign k 2
%rep 6
    PIXEL k
%assign k k + 1
%endrep

    ; the divide for the next segment's end, overlapping the segment's last 8 pixels
    mov ecx, [esp + L_COUNTTEMP]
    cmp ecx, 16
    ja .setup_not_last2
    dec ecx
    jz .fdiv_in_flight2                 ; one pixel left: no divide
    mov [esp + L_SCM1], ecx
    fild dword [esp + L_SCM1]
    fld dword [esp + L_ZISTEPU]
    fmul st0, st1                       ; zu*scm1 | scm1
    fld dword [esp + L_TDIVZSTEPU]
    fmul st0, st2                       ; tu*scm1 | zu*scm1 | scm1
    fxch st1
    faddp st3, st0
    fxch st1
    fmul dword [esp + L_SDIVZSTEPU]     ; su*scm1 | tu*scm1
    fxch st1
    faddp st3, st0
    fld dword [fp_64k]
    fxch st1
    faddp st4, st0                      ; 64k | 1/z | t/z | s/z at the span's last pixel
    fdiv st0, st1
    jmp .fdiv_in_flight2

align 4
.setup_not_last2:
    SETUP_NOT_LAST
.fdiv_in_flight2:
    mov [esp + L_COUNTTEMP], ecx
%rep 7
    PIXEL k
%assign k k + 1
%endrep

    add edi, 16
    mov [esp + L_TFRACF], edx
    mov edx, [esp + L_SNEXT]
    mov [esp + L_SFRACF], ebx
    mov ebx, [esp + L_TNEXT]
    mov [esp + L_S], edx
    mov [esp + L_T], ebx
    mov ecx, [esp + L_COUNTTEMP]
    cmp ecx, 16
    mov [edi - 1], al
    ja .not_last_segment

    ; the last segment, ecx = its steps: aimed at the span's last pixel
.last_segment:
    test ecx, ecx
    jz .e0
    S_AND_T L_SNEXT, L_TNEXT
    mov al, [esi]
    mov ebx, [esp + L_TADJUST]
    mov [edi], al
    mov eax, [esp + L_SADJUST]
    add eax, [esp + L_SNEXT]
    add ebx, [esp + L_TNEXT]
    mov ebp, [esp + L_BBEXTENTS]
    mov edx, [esp + L_BBEXTENTT]
    cmp eax, 4096
    jl .clamp_low4
    cmp eax, ebp
    ja .clamp_high4
.clamp_reentry4:
    mov [esp + L_SNEXT], eax
    cmp ebx, 4096
    jl .clamp_low5
    cmp ebx, edx
    ja .clamp_high5
.clamp_reentry5:
    cmp ecx, 1
    je .only_one_step
    sub eax, [esp + L_S]
    sub ebx, [esp + L_T]
    add eax, eax                        ; 15.17, so that the 0.31 reciprocal gives 16.48
    add ebx, ebx
    imul dword [reciprocal_16 - 8 + ecx * 4]
    mov ebp, edx                        ; s step: (snext - s) / m
    mov eax, ebx
    imul dword [reciprocal_16 - 8 + ecx * 4]
.set_entryvec:
    mov ebx, [entryvec_16 + ecx * 4]
    mov eax, edx
    mov [esp + L_JUMPTEMP], ebx
    mov ecx, ebp
    sar edx, 16
    mov ebx, [esp + L_CACHEWIDTH]
    sar ecx, 16
    imul edx, ebx
    add edx, ecx
    mov ecx, [esp + L_TFRACF]
    mov [esp + L_ADVANCE + 4], edx
    add edx, ebx
    shl ebp, 16
    mov ebx, [esp + L_SFRACF]
    shl eax, 16
    mov [esp + L_ADVANCE], edx
    mov [esp + L_TSTEP], eax
    mov edx, ecx
    add edx, eax
    sbb ecx, ecx
    add ebx, ebp
    adc esi, ADVANCE
    jmp [esp + L_JUMPTEMP]

.e0:
    mov al, [esi]
    sub edi, 15
    jmp .end_span

.only_one_step:
    sub eax, [esp + L_S]
    sub ebx, [esp + L_T]
    mov ebp, eax
    mov edx, ebx
    jmp .set_entryvec

; the entries: m steps end at [edi + 15] after edi moves back 15 - m; each takes its second step
.e1:
    sub edi, 14
    mov al, [esi]
    jmp .entry2
.e2:
    sub edi, 13
    add edx, eax
    mov al, [esi]
    sbb ecx, ecx
    add ebx, ebp
    adc esi, ADVANCE
    jmp .entry3
%assign m 3
%rep 12
%assign next m + 1
.e%[m]:
%if m == 14
    dec edi
%else
    sub edi, 15 - m
%endif
    add edx, eax
    mov al, [esi]
    sbb ecx, ecx
    add ebx, ebp
    adc esi, ADVANCE
    add edx, [esp + L_TSTEP]
    jmp .entry%[next]
%assign m m + 1
%endrep
.e15:
    add edx, eax
    mov al, [esi]
    sbb ecx, ecx
    add ebx, ebp
    adc esi, ADVANCE

    add edx, [esp + L_TSTEP]
    sbb ecx, ecx
    mov [edi + 1], al
    add ebx, ebp
    mov al, [esi]
    adc esi, ADVANCE
    add edx, [esp + L_TSTEP]
; the written-out pixels the entries join: .entryK's pixel is the last segment's (17 - K)th
%assign k 15
%rep 11
.entry%[k]:
    sbb ecx, ecx
    mov [edi + 17 - k], al
    add ebx, ebp
    mov al, [esi]
    adc esi, ADVANCE
    add edx, [esp + L_TSTEP]
%assign k k - 1
%endrep
.entry4:
    sbb ecx, ecx
    mov [edi + 13], al
    add ebx, ebp
    mov al, [esi]
    adc esi, ADVANCE
.entry3:
    mov [edi + 14], al
    mov al, [esi]
.entry2:
.end_span:
    fstp st0
    fstp st0
    fstp st0
    mov [edi + 15], al
    fldcw [esp + L_CW]
    LOOP_LEAVE LOCALS

; out of line, rarely taken: the clamps
.clamp_high_or_low0:
    jg .clamp_high0
    xor esi, esi
    jmp .clamp_reentry0
.clamp_high0:
    mov esi, [esp + L_BBEXTENTS]
    jmp .clamp_reentry0
.clamp_high_or_low1:
    jg .clamp_high1
    xor edx, edx
    jmp .clamp_reentry1
.clamp_high1:
    mov edx, [esp + L_BBEXTENTT]
    jmp .clamp_reentry1
.clamp_low2:
    mov ebp, 4096
    jmp .clamp_reentry2
.clamp_high2:
    mov ebp, [esp + L_BBEXTENTS]
    jmp .clamp_reentry2
.clamp_low3:
    mov ecx, 4096
    jmp .clamp_reentry3
.clamp_high3:
    mov ecx, [esp + L_BBEXTENTT]
    jmp .clamp_reentry3
.clamp_low4:
    mov eax, 4096
    jmp .clamp_reentry4
.clamp_high4:
    mov eax, [esp + L_BBEXTENTS]
    jmp .clamp_reentry4
.clamp_low5:
    mov ebx, 4096
    jmp .clamp_reentry5
.clamp_high5:
    mov ebx, [esp + L_BBEXTENTT]
    jmp .clamp_reentry5
