; Our fastest affine loops: fatmap2's 8:16 core unrolled and entered part-way (the first block
; starts part-way, the destination moved back to match), so no pixel pays for a loop counter; one
; pointer to the 64 KiB-aligned texture whose bh:bl is the texel's v:u.
;   fast_run_loop_asm (fast-affine):     a run of rows, the edge walking included (twin: fast_run_loop):
;                                        pixels in pairs, al then ah, one word store a pair, eight
;                                        pairs a block, an odd last pixel alone;
;   fast_column_loop_asm (fast-columns): one Mode X column (twin: fast_column_loop): eight pixels a
;                                        block, each stored alone (they lie 80 bytes apart).
;   The core, its registers and its blocks: asm/core816.inc; [esp]: the entry point.

bits 32

%include "fast.inc"
%include "loop.inc"
%include "core816.inc"

section .text

; fast_column_loop_asm: one column, pixels MODEX_ROW_BYTES apart; the map mask is the caller's.
global fast_column_loop_asm
fast_column_loop_asm:
    LOOP_ENTER 4
    mov eax, LOOP_ARG(4)
    mov ecx, [eax + FCOL_count]
    test ecx, ecx
    jle .done
    mov edi, [eax + FCOL_dst]
    mov edx, ecx
    neg edx
    and edx, 7                          ; the first block starts at pixel j = (-count) mod 8
    imul ebx, edx, MODEX_ROW_BYTES
    sub edi, ebx                        ; so that pixel j of that block is the first pixel
    mov edx, [column_entries + edx * 4]
    mov [esp], edx
    add ecx, 7
    shr ecx, 3                          ; blocks, the first one partial
    mov ebx, [eax + FCOL_texture]
    mov bl, [eax + FCOL_u_16_16 + 2]
    mov bh, [eax + FCOL_v_16_16 + 2]
    mov edx, [eax + FCOL_v_16_16]
    shl edx, 16
    mov dl, [eax + FCOL_du_16_16 + 2]
    mov dh, [eax + FCOL_dv_16_16 + 2]
    mov esi, [eax + FCOL_du_16_16]
    shl esi, 16
    mov ebp, [eax + FCOL_dv_16_16]
    shl ebp, 16
    mov eax, [eax + FCOL_u_16_16]
    shl eax, 16
    jmp [esp]
    BLOCKS MODEX_ROW_BYTES
.done:
    LOOP_LEAVE 4

; fast_run_loop_asm: a run of fast-affine's rows (twin: fast_run_loop): both edge bounds stepped in place,
; each row's span drawn by the same unrolled core. The core keeps its registers from row to row where
; it can (esi and ebp hold the fraction steps throughout); the rest of the row state lives in the frame.
L_ARGS    equ 0
L_ENTRY   equ 4
L_LINES   equ 8
L_ROW     equ 12
L_U       equ 16
L_V       equ 20
L_TEXTURE equ 24
L_STEPS   equ 28                        ; a word: du whole, dv whole
L_ODD     equ 32                        ; 1: the row's pixels are odd, the last drawn alone
L_FRAME   equ 36

; steps bound [%1] one line: q += dq, r += dr, and one more on q when r reaches d. Clobbers ebx.
%macro STEP_BOUND 1
    mov ebx, [%1 + BOUND_dq]
    add [%1 + BOUND_q], ebx
    mov ebx, [%1 + BOUND_r]
    add ebx, [%1 + BOUND_dr]
    cmp ebx, [%1 + BOUND_d]
    jb %%stepped
    sub ebx, [%1 + BOUND_d]
    inc dword [%1 + BOUND_q]
%%stepped:
    mov [%1 + BOUND_r], ebx
%endmacro

global fast_run_loop_asm
fast_run_loop_asm:
    LOOP_ENTER L_FRAME
    mov ecx, LOOP_ARG(L_FRAME)
    mov eax, [ecx + RUN_lines]
    test eax, eax
    jle .done
    mov [esp + L_ARGS], ecx
    mov [esp + L_LINES], eax
    mov eax, [ecx + RUN_row]
    mov [esp + L_ROW], eax
    mov eax, [ecx + RUN_u_16_16]
    mov [esp + L_U], eax
    mov eax, [ecx + RUN_v_16_16]
    mov [esp + L_V], eax
    mov eax, [ecx + RUN_texture]
    mov [esp + L_TEXTURE], eax
    mov al, [ecx + RUN_du_16_16 + 2]
    mov ah, [ecx + RUN_dv_16_16 + 2]
    mov [esp + L_STEPS], ax
    mov esi, [ecx + RUN_du_16_16]
    shl esi, 16                         ; du fraction
    mov ebp, [ecx + RUN_dv_16_16]
    shl ebp, 16                         ; dv fraction
.row:
    mov ecx, [esp + L_ARGS]
    mov edx, [ecx + RUN_lower]
    mov eax, [edx + BOUND_q]            ; the first pixel, before the clip
    STEP_BOUND edx
    cmp eax, [ecx + RUN_clip_lo]
    jge .lo_inside
    mov eax, [ecx + RUN_clip_lo]
.lo_inside:
    mov edx, [ecx + RUN_upper]
    mov edi, [edx + BOUND_q]            ; the last pixel
    STEP_BOUND edx
    cmp edi, [ecx + RUN_clip_hi]
    jle .hi_inside
    mov edi, [ecx + RUN_clip_hi]
.hi_inside:
    sub edi, eax
    jl .next_row                        ; nothing on this row
    inc edi                             ; the span's pixels
    mov edx, [ecx + RUN_tally]
    inc dword [edx]
    add [edx + 4], edi
    mov ebx, eax
    imul ebx, [ecx + RUN_du_16_16]
    add ebx, [esp + L_U]                ; u at the first pixel
    mov edx, eax
    imul edx, [ecx + RUN_dv_16_16]
    add edx, [esp + L_V]                ; v at the first pixel
    add eax, [esp + L_ROW]              ; its address
    mov ecx, edi
    and edi, 1
    mov [esp + L_ODD], edi              ; an odd pixel, drawn after the pairs
    shr ecx, 1                          ; pairs
    PAIR_ENTRY eax, edi, run_entries    ; blocks, the first one partial; 0 (ZF): no pair, one pixel
    mov edi, eax
    mov eax, ebx                        ; (mov and ror leave ZF as shr set it)
    ror eax, 16                         ; u: fraction in the high half, whole in al
    ror edx, 16                         ; v: the same, whole in dl
    mov ebx, [esp + L_TEXTURE]
    mov bl, al
    mov bh, dl
    mov dx, [esp + L_STEPS]
    jz .odd_pixel
    PAIRS_AND_ODD .next_row
.next_row:
    mov ecx, [esp + L_ARGS]
    mov eax, [ecx + RUN_u_row_16_16]
    add [esp + L_U], eax
    mov eax, [ecx + RUN_v_row_16_16]
    add [esp + L_V], eax
    mov eax, [ecx + RUN_pitch]
    add [esp + L_ROW], eax
    dec dword [esp + L_LINES]
    jnz .row
.done:
    LOOP_LEAVE L_FRAME

section .rodata
align 4
column_entries:
    dd fast_column_loop_asm.e0, fast_column_loop_asm.e1, fast_column_loop_asm.e2, fast_column_loop_asm.e3
    dd fast_column_loop_asm.e4, fast_column_loop_asm.e5, fast_column_loop_asm.e6, fast_column_loop_asm.e7
run_entries:
    dd fast_run_loop_asm.e0, fast_run_loop_asm.e1, fast_run_loop_asm.e2, fast_run_loop_asm.e3
    dd fast_run_loop_asm.e4, fast_run_loop_asm.e5, fast_run_loop_asm.e6, fast_run_loop_asm.e7
