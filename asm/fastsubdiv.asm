; fast_subdiv_loop_asm (fast-subdiv-N): one span, segment by segment; twin of
; kernel/mappers/fastsubdiv.cpp (fast_subdiv_loop), which it matches bit for bit. Each exact point
; in x87 as the twin computes it (53-bit precision, the same operations in the same order, the
; 64-bit conversion rounding to nearest), the steps between two points by their 32-bit difference,
; the pixels by the 8:16 core (asm/core816.inc), entered part-way as fast_run_loop_asm enters it:
; a row (stride 1) in pairs, one word store a pair; a column (any other stride) a pixel at a time,
; the destination moved by the stride from the frame after each store. A span of one or two pixels
; (fast_subdiv_short) stores its exact points' texels, without the frame or the core.

bits 32

%include "fastsubdiv.inc"
%include "loop.inc"
%include "core816.inc"

section .rodata
align 8
subpixel_one: dq 256.0                  ; SUBPIXEL_ONE: a pixel in subpixels
scale_16_16:  dq 65536.0

L_ARGS        equ 0
L_LEFT        equ 4                     ; pixels from the segment's first to the span's end
L_DST         equ 8                     ; the segment's first pixel's address
L_U0          equ 12                    ; 16.16 at the segment's first pixel
L_V0          equ 16
L_U1          equ 20                    ; qword: 16.16 at its next exact point (the low dword kept)
L_V1          equ 28                    ; qword
L_TEXTURE     equ 36
L_N           equ 40                    ; a full segment's pixels
L_SHIFT       equ 44                    ; log2 of them
L_FULL_ENTRY  equ 48                    ; a full segment's entry into the pairs
L_FULL_BLOCKS equ 52                    ; and its blocks
L_FULL_BACK   equ 56                    ; and how far its destination moves back (0 or less)
L_ENTRY       equ 60                    ; the last segment's entry
L_ODD         equ 64                    ; 1: an odd last pixel after the pairs (the last segment's)
L_LAST        equ 68                    ; the span's last pixel, the last segment's exact point
L_D           equ 72                    ; the last segment's divisor
L_SEG_X       equ 76                    ; qword: a full segment in subpixels, n * 256
L_STRIDE      equ 84                    ; bytes from a pixel to the next
L_SEG_BYTES   equ 88                    ; bytes from a full segment's first pixel to the next's
L_FRAME       equ 92

section .text

; the exact point at x (st0, kept) into [esp + L_U1], [esp + L_V1] (or the two offsets given);
; ecx (or the register given third): the block
%macro POINT 0
    POINT_AT L_U1, L_V1
%endmacro
%macro POINT_AT 2-3 ecx
    fld qword [%3 + FSUB_g]
    fmul st0, st1
    fadd qword [%3 + FSUB_c]           ; q = c0 + g0 x
    fld qword [%3 + FSUB_g + 8]
    fmul st0, st2
    fadd qword [%3 + FSUB_c + 8]       ; pu
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + %1]              ; u in 16.16, nearest
    fld qword [%3 + FSUB_g + 16]
    fmul st0, st2
    fadd qword [%3 + FSUB_c + 16]      ; pv
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + %2]
    fstp st0                            ; q
%endmacro

; the texel of the 16.16 point at [esp + %1], [esp + %2] into %3; %4: the texture (64 KiB
; aligned; the block's by default, edx holding the block); ecx clobbered
%macro TEXEL_AT 3-4 [edx + FSUB_texture]
    movzx ecx, byte [esp + %1 + 2]      ; u whole
    mov ch, [esp + %2 + 2]              ; v whole
    add ecx, %4
    mov %3, [ecx]
%endmacro

; the core's registers (asm/core816.inc) from the steps du (eax) and dv (edx) and the segment's
; start [esp + L_U0], [esp + L_V0]
%macro CORE_LOAD 0
    mov esi, eax
    shl esi, 16                         ; du fraction
    mov ebp, edx
    shl ebp, 16                         ; dv fraction
    shr eax, 16                         ; al: du whole
    shr edx, 16
    mov ah, dl                          ; ah: dv whole
    mov ebx, [esp + L_TEXTURE]
    mov bl, [esp + L_U0 + 2]            ; u whole
    mov bh, [esp + L_V0 + 2]            ; v whole
    mov edx, [esp + L_V0]
    shl edx, 16                         ; v fraction
    mov dx, ax                          ; dl: du whole, dh: dv whole
    mov eax, [esp + L_U0]
    shl eax, 16                         ; u fraction
%endmacro

; Columns: each pixel stored, then the destination moved on by the stride; blocks of eight
; entered at .e0 to .e7 (the pixel the first block starts at: nothing to move back), ecx of them.
%macro STRIDE_PIXEL 0
    PIXEL 0
    add edi, [esp + L_STRIDE]
%endmacro
%macro STRIDE_BLOCKS 0
.block:
.e0: STRIDE_PIXEL
.e1: STRIDE_PIXEL
.e2: STRIDE_PIXEL
.e3: STRIDE_PIXEL
.e4: STRIDE_PIXEL
.e5: STRIDE_PIXEL
.e6: STRIDE_PIXEL
.e7: STRIDE_PIXEL
    dec ecx
    jnz .block
%endmacro

; The computed entry into STRIDE_BLOCKS for ecx pixels (in; out: the blocks): the first block
; starts at pixel (-pixels) mod 8, [esp + L_ENTRY] takes that entry of the table %2; %1: scratch.
%macro PIXEL_ENTRY 2
    mov %1, ecx
    neg %1
    and %1, 7
    mov %1, [%2 + %1 * 4]
    mov [esp + L_ENTRY], %1
    add ecx, 7
    shr ecx, 3
%endmacro

; One span, rows (%1 = rows: stride 1, pairs) or columns (%1 = columns: the stride's); %2: the
; entry table. Full segments keep x (the next exact point's, in subpixels) on the x87 stack, one
; add of n * 256 a segment (exact: whole numbers below 2^53, as the twin's x0 + k * 256); their
; entry into the blocks is the same every time, found once a span. The last segment (at most n
; pixels, its exact point the span's last pixel) finds its own and divides.
%macro SUBDIV_SPAN 2
    LOOP_ENTER L_FRAME
    mov edx, LOOP_ARG(L_FRAME)
    mov eax, [edx + FSUB_count]
    test eax, eax
    jle .done
    mov [esp + L_ARGS], edx
    mov [esp + L_LEFT], eax
    dec eax
    mov [esp + L_LAST], eax
    FRAME_COPY edx, FSUB_dst, L_DST, FSUB_texture, L_TEXTURE
    mov ecx, [edx + FSUB_shift]
    mov [esp + L_SHIFT], ecx
    mov eax, [edx + FSUB_stride]
    mov [esp + L_STRIDE], eax
    mov ebx, 1
    shl ebx, cl
    mov [esp + L_N], ebx
    cmp [esp + L_LEFT], ebx
    jle .first_point                    ; one segment: none of a full segment's set-up
    mov dword [esp + L_ODD], 0          ; (a full segment's pixels are pairs)
    shl eax, cl
    mov [esp + L_SEG_BYTES], eax        ; n * stride
    shl ebx, 8
    mov [esp + L_D], ebx
    fild dword [esp + L_D]
    fstp qword [esp + L_SEG_X]          ; n * 256, exact
    mov ecx, [esp + L_N]
    xor edi, edi
%ifidn %1, rows
    shr ecx, 1                          ; a full segment's pairs
    PAIR_ENTRY edi, eax, %2
%else
    PIXEL_ENTRY eax, %2
%endif
    mov [esp + L_FULL_BACK], edi
    mov [esp + L_FULL_BLOCKS], ecx
    mov eax, [esp + L_ENTRY]
    mov [esp + L_FULL_ENTRY], eax
    mov ecx, edx
    fldz
    fadd qword [ecx + FSUB_x]           ; x at pixel 0 (0 + x0, as the twin's x0 + 0 * 256)
    POINT_AT L_U0, L_V0                 ; (qword stores, u's first: its high dword is then
                                        ; overwritten by v's low one, and v's high one lands in
                                        ; U1, written again before it is read)
    jmp .full_segment
.first_point:                           ; one segment: its first point, then the last
    mov ecx, edx
    fldz
    fadd qword [ecx + FSUB_x]
    POINT_AT L_U0, L_V0
    jmp .last_segment
.full_segment:                          ; more than n pixels left: n of them, to the exact point n on
    fadd qword [esp + L_SEG_X]
    mov ecx, [esp + L_ARGS]
    POINT
    mov ecx, [esp + L_SHIFT]
    mov eax, [esp + L_U1]
    sub eax, [esp + L_U0]
    sar eax, cl                         ; du
    mov edx, [esp + L_V1]
    sub edx, [esp + L_V0]
    sar edx, cl                         ; dv
    mov edi, [esp + L_DST]
    add edi, [esp + L_FULL_BACK]
    mov ecx, [esp + L_FULL_BLOCKS]
    CORE_LOAD
    jmp [esp + L_FULL_ENTRY]
.last_segment:                          ; the pixels left, to the exact point at the last
    fstp st0                            ; (the full segments' x)
    mov eax, [esp + L_LEFT]
    dec eax
    jz .one_pixel
    mov [esp + L_D], eax
    mov ecx, [esp + L_ARGS]
    fild dword [esp + L_LAST]
    fmul qword [subpixel_one]
    fadd qword [ecx + FSUB_x]           ; x = x0 + last * 256
    POINT
    fstp st0
    cmp eax, 1                          ; (d: POINT leaves eax)
    je .two_pixels
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
    jmp .last_draw
.one_pixel:                             ; the texel at the segment's first point, stored (the core's
                                        ; first pixel, without its set-up: a last segment of one or
                                        ; two pixels after full ones; shorter spans: fast_subdiv_short)
    TEXEL_AT L_U0, L_V0, al, [esp + L_TEXTURE]
    mov edi, [esp + L_DST]
    mov [edi], al
    jmp .done                           ; (the last segment)
.two_pixels:                            ; the two exact points' texels: the core's second pixel is
                                        ; U0 + (U1 - U0) / 1, the second point itself
    TEXEL_AT L_U0, L_V0, al, [esp + L_TEXTURE]
    TEXEL_AT L_U1, L_V1, ah, [esp + L_TEXTURE]
    mov edi, [esp + L_DST]
%ifidn %1, rows
    mov [edi], ax
%else
    mov [edi], al
    add edi, [esp + L_STRIDE]
    mov [edi], ah
%endif
    jmp .done
.last_draw:                             ; eax: du, edx: dv
    mov ecx, [esp + L_LEFT]
    mov edi, [esp + L_DST]
%ifidn %1, rows
    mov ebx, ecx
    and ebx, 1
    mov [esp + L_ODD], ebx
    shr ecx, 1                          ; pairs
    PAIR_ENTRY edi, ebx, %2             ; blocks, the first one partial
    CORE_LOAD                           ; (leaves ecx and edi)
    test ecx, ecx
    jz .odd_pixel                       ; no pair: one pixel
    PAIRS_AND_ODD .next
%else
    PIXEL_ENTRY ebx, %2                 ; blocks, the first one partial
    CORE_LOAD
    jmp [esp + L_ENTRY]
    STRIDE_BLOCKS
%endif
.next:
    mov eax, [esp + L_N]
    mov ecx, [esp + L_LEFT]
    sub ecx, eax
    jle .done                           ; that was the last segment
    mov edx, [esp + L_SEG_BYTES]
    add [esp + L_DST], edx
    mov [esp + L_LEFT], ecx
    mov edx, [esp + L_U1]
    mov [esp + L_U0], edx
    mov edx, [esp + L_V1]
    mov [esp + L_V0], edx
    cmp ecx, eax
    jg .full_segment
    jmp .last_segment
.done:
    LOOP_LEAVE L_FRAME
%endmacro

; Rows go on here; any other stride to the column loop (the same frame and argument).
global fast_subdiv_loop_asm
fast_subdiv_loop_asm:
    mov edx, [esp + 4]
    mov eax, [edx + FSUB_count]
    dec eax
    cmp eax, 1
    jbe fast_subdiv_short               ; one or two pixels
    cmp dword [edx + FSUB_stride], 1
    jne fast_subdiv_column_asm
    SUBDIV_SPAN rows, pair_entries

fast_subdiv_column_asm:
    SUBDIV_SPAN columns, column_entries

; A span of one or two pixels (most of a mesh's: triangles of a dozen pixels), rows or columns:
; its exact points' texels (the second pixel's step is the second point less the first, so the
; core would read the second point's texel), with no frame, no saved register and no core; edx:
; the block, eax: the pixels less one.
fast_subdiv_short:
    sub esp, 32                         ; U0, V0, U1, V1 (qwords)
    fldz
    fadd qword [edx + FSUB_x]           ; x at pixel 0, as the twin's x0 + 0 * 256
    POINT_AT 0, 8, edx
    test eax, eax
    jnz .two
    fstp st0
    TEXEL_AT 0, 8, al
    mov ecx, [edx + FSUB_dst]
    mov [ecx], al
    add esp, 32
    ret
.two:
    fadd qword [subpixel_one]           ; pixel 1: x0 + 256
    POINT_AT 16, 24, edx
    fstp st0
    TEXEL_AT 0, 8, al
    TEXEL_AT 16, 24, ah
    mov ecx, [edx + FSUB_dst]
    mov [ecx], al
    add ecx, [edx + FSUB_stride]
    mov [ecx], ah
    add esp, 32
    ret

section .rodata
align 4
    ENTRIES pair_entries, fast_subdiv_loop_asm, 8
    ENTRIES column_entries, fast_subdiv_column_asm, 8
