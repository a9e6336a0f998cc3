; A frame's triangle for the fast run loops in one call (twins: kernel/mappers/fast_triangle.cpp):
; fast_triangle_asm sets it up (SETUP_TRIANGLE), finds its rows' chains (TRI_ROWS) and two runs
; (RUN_FROM), and writes the run loop's block (asm/fast.asm's loops draw it); fast_triangle_runs_asm
; does the same from the rows on, fast_triangle_enveloped_asm after auto's envelope's guards.

bits 32

%include "fast.inc"
%include "fast_triangle.inc"
%include "setup.inc"
%include "walk.inc"
%include "surface.inc"
%include "envelope.inc"
%include "loop.inc"
%include "triangle_setup.inc"
%include "triangle_rows.inc"

section .text

; fast_triangle_asm(FastTriangleArgs* a): a triangle in range for the fast run loops, its setup and
; its walk's set-up in one call (twin: fast_triangle, kernel/mappers/fast.cpp): SETUP_TRIANGLE, then
; the rows whose centre lies in its box inside the target's clip (box_lines), their chains
; (TRI_ROWS, the box under 64 pixels a side) and their two runs (RUN_FROM), and the run loop's block
; from them: the runs, the first row's address, the pitch and the clip's columns, u and v at pixel
; 0 of the row, the steps, `inside`. Returns 1; 2 with only the setup written where the walker must
; walk it; 0 where C++ must set it up.
F_LINE    equ R_FRAME                   ; the first row
F_OX      equ F_LINE + 4                ; the chains' origin (TRI_ROWS)
F_OY      equ F_LINE + 8
F_FRAME   equ S_FRAME > F_OY + 4 ? S_FRAME : F_OY + 4   ; (the setup's frame, then the walk's)

; the u or v plane at %1 of the setup at esi, into the block at ebx at row ecx, pixel 0 (%2, at the
; block's %3 and %4 the steps across and down): FixedPlane::value(0, row), modulo 2^32
%macro RUN_PLANE 4
    mov eax, ecx
    sub eax, [esi + %1 + FIX_y0]
    mov edx, [esi + %1 + FIX_dy]
    mov [ebx + %4], edx
    imul eax, edx
    add eax, [esi + %1 + FIX_at]
    mov edx, [esi + %1 + FIX_dx]
    mov [ebx + %3], edx
    imul edx, [esi + %1 + FIX_x0]
    sub eax, edx
    mov [ebx + %2], eax
%endmacro

; the entry of the two routines below that set a triangle up: ebp the setup then
%macro TRIANGLE_ENTER 0
    LOOP_ENTER F_FRAME
    mov ebx, LOOP_ARG(F_FRAME)
    mov esi, [ebx + FTRI_in]
    mov ebp, [ebx + FTRI_setup]
    SETUP_TRIANGLE
%endmacro

global fast_triangle_asm
fast_triangle_asm:
    TRIANGLE_ENTER
    mov esi, ebp                        ; the setup
    mov ebp, LOOP_ARG(F_FRAME)
.runs:                                  ; (fast_triangle_runs_asm joins here: esi the setup, ebp the block)
    ; the rows whose centre lies in the box, inside the clip (box_lines)
    mov eax, [esi + PS_min_y]
    lea ecx, [eax + 127]
    sar ecx, 8
    mov edi, [ebp + FTRI_target]
    mov edx, [edi + TGT_clip + CLIP_y0]
    MAX_SIGNED ecx, edx
    mov edx, [esi + PS_max_y]
    mov ebx, edx
    sub edx, 128
    sar edx, 8
    mov edi, [edi + TGT_clip + CLIP_y1]
    dec edi
    MIN_SIGNED edx, edi
    cmp ecx, edx
    jg .empty
    mov [esp + F_LINE], ecx
    mov [esp + R_LAST], edx
    ; the box under 64 pixels a side (small_box)
    sub ebx, eax
    cmp ebx, 64 << 8
    jge .walk
    mov ebx, [esi + PS_min_x]
    mov edi, [esi + PS_max_x]
    sub edi, ebx
    cmp edi, 64 << 8
    jge .walk
    ; the chains (TRI_ROWS, from the pixel corner at or below the box)
    sar ebx, 8
    mov [esp + F_OX], ebx
    shl ebx, 8
    mov [esp + T_OMIN], ebx
    sar eax, 8
    mov [esp + F_OY], eax
    sub ecx, eax
    mov [esp + T_FIRST], ecx
    sub edx, eax
    mov [esp + T_LAST], edx
    shl eax, 8
    mov [esp + T_OMAJ], eax
    lea eax, [ebp + FTRI_lower]
    mov [esp + T_LOWER], eax
    lea eax, [ebp + FTRI_upper]
    mov [esp + T_UPPER], eax
    add esi, PS_edges
    TRI_ROWS .walk, {[esp + F_OX]}, {[esp + F_OY]}, {lea edi, [ebp + FTRI_lower]}, {lea edi, [ebp + FTRI_upper]}
    ; the first run, then the second from the row after it, which must end at the last
    mov ebx, [ebp + FTRI_run]
    lea esi, [ebp + FTRI_lower]
    lea edi, [ebp + FTRI_upper]
    mov ecx, [esp + F_LINE]
    RUN_FROM .walk
    mov [ebx + RUN_lower], esi
    mov [ebx + RUN_upper], edi
    mov edx, eax
    sub edx, ecx
    inc edx
    mov [ebx + RUN_lines], edx
    lea ecx, [eax + 1]
    cmp ecx, [esp + R_LAST]
    jg .one
    RUN_FROM .walk
    cmp eax, [esp + R_LAST]
    jne .walk                           ; (a third run: not a triangle's)
    lea edx, [eax + 1]
    sub edx, ecx
    jmp .next
.one:                                   ; no second run
    xor edx, edx
    xor esi, esi
    xor edi, edi
.next:
    mov [ebx + RUN_next_lines], edx
    mov [ebx + RUN_next_lower], esi
    mov [ebx + RUN_next_upper], edi
    ; the first row, the clip's columns, u and v at pixel 0 of the row, the steps
    mov esi, [ebp + FTRI_setup]
    mov edi, [ebp + FTRI_target]
    mov ecx, [esp + F_LINE]
    mov eax, [edi + TGT_pitch]
    mov [ebx + RUN_pitch], eax
    imul eax, ecx
    add eax, [edi + TGT_base]
    mov [ebx + RUN_row], eax
    mov eax, [edi + TGT_clip + CLIP_x0]
    mov [ebx + RUN_clip_lo], eax
    mov eax, [edi + TGT_clip + CLIP_x1]
    dec eax
    mov [ebx + RUN_clip_hi], eax
    RUN_PLANE PS_u_fx, RUN_u_16_16, RUN_du_16_16, RUN_u_row_16_16
    RUN_PLANE PS_v_fx, RUN_v_16_16, RUN_dv_16_16, RUN_v_row_16_16
    ; inside: the box within the clip's columns (min_x >= x0 * 256, max_x <= x1 * 256)
    xor eax, eax
    mov edx, [edi + TGT_clip + CLIP_x0]
    shl edx, 8
    cmp [esi + PS_min_x], edx
    jl .inside
    mov edx, [edi + TGT_clip + CLIP_x1]
    shl edx, 8
    cmp [esi + PS_max_x], edx
    setle al
.inside:
    mov [ebx + RUN_inside], eax
    mov eax, TRIANGLE_RUNS
    jmp .done
.empty:                                 ; no row: `lines` 0 alone
    mov ebx, [ebp + FTRI_run]
    mov dword [ebx + RUN_lines], 0
    mov eax, TRIANGLE_RUNS
    jmp .done
.walk:
    mov eax, TRIANGLE_TO_WALKER
    jmp .done
    SETUP_EXITS F_FRAME

; fast_triangle_runs_asm(FastTriangleArgs* a): the same for a triangle set up already (`setup` read,
; of its planes the 16.16 ones only): from the rows on (twin: fast_triangle_runs). Returns 1, or 2
; where the walker must walk it.
global fast_triangle_runs_asm
fast_triangle_runs_asm:
    LOOP_ENTER F_FRAME
    mov ebp, LOOP_ARG(F_FRAME)
    mov esi, [ebp + FTRI_setup]
    jmp fast_triangle_asm.runs

; fast_triangle_enveloped_asm(FastTriangleArgs* a): fast_triangle_asm for auto's envelope (twin:
; fast_triangle_enveloped): after the setup, within_envelope (kernel/core/envelope.h) with the limits
; at `envelope`, in integers: the box's sides (the low halves: in range they are below 2^23
; subpixels) within the extents and their sum within the reach, D (twice the area) within the
; limits' area2, W H <= 16384 D where D is below 2^22 (4 W H <= 65536 D; above, at once: W H is
; below 2^36), and the four 16.16 steps within 32766 texels. Returns 3 (the setup written) where one
; fails, else as fast_triangle_asm.
global fast_triangle_enveloped_asm
fast_triangle_enveloped_asm:
    TRIANGLE_ENTER
    mov edi, LOOP_ARG(F_FRAME)
    mov edi, [edi + FTRI_envelope]
    mov eax, [ebp + PS_max_x]
    sub eax, [ebp + PS_min_x]           ; W
    cmp eax, [edi + ENV_extent_x]
    jg .unproven
    mov ecx, [ebp + PS_max_y]
    sub ecx, [ebp + PS_min_y]           ; H
    cmp ecx, [edi + ENV_extent_y]
    jg .unproven
    lea edx, [eax + ecx]
    cmp edx, ENVELOPE_REACH_SUBPIXELS
    ja .unproven
    mov ebx, [ebp + PS_area2]           ; D, low
    mov esi, [ebp + PS_area2 + 4]       ; and high
    cmp esi, [edi + ENV_area2 + 4]
    jg .unproven
    jl .area
    cmp ebx, [edi + ENV_area2]
    ja .unproven
.area:
    test esi, esi
    jnz .steps
    cmp ebx, 1 << 22
    jae .steps
    mul ecx                             ; edx:eax = W H
    mov esi, ebx
    shr esi, 18
    shl ebx, 14                         ; esi:ebx = 16384 D
    cmp edx, esi
    ja .unproven
    jb .steps
    cmp eax, ebx
    ja .unproven
.steps:
%assign ENV_STEP 32766 << 16
%macro STEP_WITHIN 1
    mov eax, [ebp + %1]
    add eax, ENV_STEP
    cmp eax, 2 * ENV_STEP
    ja .unproven
%endmacro
    STEP_WITHIN PS_u_fx + FIX_dx
    STEP_WITHIN PS_u_fx + FIX_dy
    STEP_WITHIN PS_v_fx + FIX_dx
    STEP_WITHIN PS_v_fx + FIX_dy
    mov esi, ebp                        ; the setup
    mov ebp, LOOP_ARG(F_FRAME)
    jmp fast_triangle_asm.runs
.unproven:
    mov eax, TRIANGLE_OUTSIDE_ENVELOPE
    jmp fast_triangle_asm.done          ; (the same frame)
.refuse_pop:
    jmp fast_triangle_asm.refuse_pop
.refuse:
    jmp fast_triangle_asm.refuse
