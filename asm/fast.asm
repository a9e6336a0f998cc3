; Our fastest affine loops (fast-affine rows, fast-columns): fatmap2's 8:16 core unrolled eight
; times and entered part-way (the first block starts at pixel (-count) mod 8, the destination moved
; back to match), so no pixel pays for a loop counter; one pointer to the 64 KiB-aligned texture
; whose bh:bl is the texel's v:u. Twins: fatmap16_loop (rows) and fast_column_loop (columns) in
; kernel/raster.
;   al: texel   eax 31..16: u fraction   ebx: texture | v whole (bh) | u whole (bl)
;   edx 31..16: v fraction, dh: dv whole, dl: du whole   esi 31..16: du fraction   ebp 31..16: dv fraction
;   edi: destination   ecx: blocks of 8 left   [esp]: the entry point

bits 32

%include "offsets.inc"

%macro PIXEL 1                          ; %1: the destination offset within the block
    mov al, [ebx]
    add edx, ebp                        ; v fraction (the low half of ebp is 0)
    adc bh, dh                          ; v whole, plus the carry
    add eax, esi                        ; u fraction
    adc bl, dl                          ; u whole, plus the carry
    mov [edi + %1], al
%endmacro

; The shared set-up. %1: args offsets prefix (FATMAP / FCOL), %2: bytes between pixels,
; %3: the entry table. Leaves every register as the loop wants it.
%macro SETUP 3
    push ebp
    push ebx
    push esi
    push edi
    sub esp, 4
    mov eax, [esp + 24]
    mov ecx, [eax + %1_COUNT]
    test ecx, ecx
    jle .done
    mov edi, [eax + %1_DST]
    mov edx, ecx
    neg edx
    and edx, 7                          ; the first block starts at pixel j = (-count) mod 8
    imul ebx, edx, %2
    sub edi, ebx                        ; so that pixel j of that block is the first pixel
    mov edx, [%3 + edx * 4]
    mov [esp], edx
    add ecx, 7
    shr ecx, 3                          ; blocks, the first one partial
    mov ebx, [eax + %1_TEXTURE]
    mov bl, [eax + %1_U + 2]
    mov bh, [eax + %1_V + 2]
    mov edx, [eax + %1_V]
    shl edx, 16
    mov dl, [eax + %1_DU + 2]
    mov dh, [eax + %1_DV + 2]
    mov esi, [eax + %1_DU]
    shl esi, 16
    mov ebp, [eax + %1_DV]
    shl ebp, 16
    mov eax, [eax + %1_U]
    shl eax, 16
    jmp [esp]
%endmacro

%macro FINISH 0
.done:
    add esp, 4
    pop edi
    pop esi
    pop ebx
    pop ebp
    ret
%endmacro

section .text

global fast_row_asm
fast_row_asm:
    SETUP FATMAP, 1, row_entries
.block:
.e0: PIXEL 0
.e1: PIXEL 1
.e2: PIXEL 2
.e3: PIXEL 3
.e4: PIXEL 4
.e5: PIXEL 5
.e6: PIXEL 6
.e7: PIXEL 7
    add edi, 8
    dec ecx
    jnz .block
    FINISH

global fast_column_asm
fast_column_asm:
    SETUP FCOL, MODEX_ROW_BYTES, column_entries
.block:
.e0: PIXEL 0
.e1: PIXEL MODEX_ROW_BYTES
.e2: PIXEL 2 * MODEX_ROW_BYTES
.e3: PIXEL 3 * MODEX_ROW_BYTES
.e4: PIXEL 4 * MODEX_ROW_BYTES
.e5: PIXEL 5 * MODEX_ROW_BYTES
.e6: PIXEL 6 * MODEX_ROW_BYTES
.e7: PIXEL 7 * MODEX_ROW_BYTES
    add edi, 8 * MODEX_ROW_BYTES
    dec ecx
    jnz .block
    FINISH

section .rodata
align 4
row_entries:
    dd fast_row_asm.e0, fast_row_asm.e1, fast_row_asm.e2, fast_row_asm.e3
    dd fast_row_asm.e4, fast_row_asm.e5, fast_row_asm.e6, fast_row_asm.e7
column_entries:
    dd fast_column_asm.e0, fast_column_asm.e1, fast_column_asm.e2, fast_column_asm.e3
    dd fast_column_asm.e4, fast_column_asm.e5, fast_column_asm.e6, fast_column_asm.e7
